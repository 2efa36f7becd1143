#include "server/config.h"

#include <functional>
#include <map>

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"

namespace swarmplan::server {
namespace {

using Setter = std::function<absl::Status(ServerConfig&, const std::string&)>;

struct Setting {
  const char* flag;
  const char* help;
  Setter set;
};

absl::Status Bad(const std::string& flag, const std::string& value, const char* expected) {
  return absl::InvalidArgumentError(absl::StrCat("--", flag, ": '", value, "' is not ", expected));
}

Setter String(std::string ServerConfig::*field) {
  return [field](ServerConfig& c, const std::string& v) {
    c.*field = v;
    return absl::OkStatus();
  };
}

template <typename Int>
Setter Integer(Int ServerConfig::*field, const char* flag, int64_t min) {
  return [field, flag, min](ServerConfig& c, const std::string& v) {
    int64_t n = 0;
    if (!absl::SimpleAtoi(v, &n) || n < min) {
      return Bad(flag, v, absl::StrCat("an integer >= ", min).c_str());
    }
    c.*field = static_cast<Int>(n);
    return absl::OkStatus();
  };
}

Setter Duration(absl::Duration ServerConfig::*field, const char* flag) {
  return [field, flag](ServerConfig& c, const std::string& v) {
    absl::Duration d;
    double seconds = 0;
    if (absl::SimpleAtod(v, &seconds) && seconds >= 0) {
      c.*field = absl::Seconds(seconds);
      return absl::OkStatus();
    }
    if (!absl::ParseDuration(v, &d) || d < absl::ZeroDuration()) {
      return Bad(flag, v, "a duration (seconds, or like 90s, 5m, 2h)");
    }
    c.*field = d;
    return absl::OkStatus();
  };
}

const std::vector<Setting>& Settings() {
  static const auto* settings = new std::vector<Setting>{
      {"listen", "gRPC address host:port (port 0: any free port)", String(&ServerConfig::listen)},
      {"metrics-port", "Prometheus /metrics port; 0 disables; -1 picks a free port",
       Integer(&ServerConfig::metrics_port, "metrics-port", -1)},
      {"metrics-address", "address the metrics endpoint binds",
       String(&ServerConfig::metrics_address)},
      {"data-dir", "directory of the embedded SQLite store", String(&ServerConfig::data_dir)},
      {"store",
       "sqlite:DIR (embedded) or redis://HOST[:PORT][/DB] (shared); default: sqlite:--data-dir",
       String(&ServerConfig::store)},
      {"store-password-file", "file holding the Redis password (redis:// stores)",
       String(&ServerConfig::store_password_file)},
      {"workers", "planning threads; 0: number of cores",
       Integer(&ServerConfig::workers, "workers", 0)},
      {"queue-capacity", "queued jobs before RESOURCE_EXHAUSTED",
       Integer(&ServerConfig::queue_capacity, "queue-capacity", 1)},
      {"job-retention", "how long finished jobs are kept",
       Duration(&ServerConfig::job_retention, "job-retention")},
      {"max-retained-jobs", "finished jobs kept at most; the oldest beyond are deleted",
       Integer(&ServerConfig::max_retained_jobs, "max-retained-jobs", 1)},
      {"job-cache-entries", "finished jobs held in memory (the rest are read from the store)",
       Integer(&ServerConfig::job_cache_entries, "job-cache-entries", 0)},
      {"map-cache-entries",
       "parsed maps held in memory (the others are parsed from the store when planned on)",
       Integer(&ServerConfig::map_cache_entries, "map-cache-entries", 0)},
      {"shutdown-grace", "time running jobs get to finish on SIGTERM",
       Duration(&ServerConfig::shutdown_grace, "shutdown-grace")},
      {"job-lease",
       "redis:// stores: a job whose replica stops renewing its lease this long runs elsewhere",
       Duration(&ServerConfig::job_lease, "job-lease")},
      {"max-message-bytes", "largest gRPC message",
       Integer(&ServerConfig::max_message_bytes, "max-message-bytes", 1)},
      {"max-map-cells", "largest grid or terrain, in cells",
       Integer(&ServerConfig::max_map_cells, "max-map-cells", 1)},
      {"max-population", "largest population a request may ask for",
       Integer(&ServerConfig::max_population, "max-population", 1)},
      {"max-iterations", "iteration cap of every job",
       Integer(&ServerConfig::max_iterations, "max-iterations", 1)},
      {"max-job-time", "time budget cap (and default) of every job",
       Duration(&ServerConfig::max_job_time, "max-job-time")},
      {"max-watchers-per-job", "concurrent streams on one job",
       Integer(&ServerConfig::max_watchers_per_job, "max-watchers-per-job", 1)},
      {"optimum-budget", "time for each result's exact optimum (cached per query); 0: off",
       Duration(&ServerConfig::optimum_budget, "optimum-budget")},
      {"max-page-bytes",
       "largest ListMaps/ListJobs page in bytes (at most half of --max-message-bytes)",
       Integer(&ServerConfig::max_page_bytes, "max-page-bytes", 1024)},
      {"token-file", "file holding the bearer token clients must send; empty: no auth",
       String(&ServerConfig::token_file)},
      {"tls-cert-file", "PEM certificate chain; with --tls-key-file enables TLS",
       String(&ServerConfig::tls_cert_file)},
      {"tls-key-file", "PEM private key", String(&ServerConfig::tls_key_file)},
      {"log-level", "trace, debug, info, warn, error", String(&ServerConfig::log_level)},
  };
  return *settings;
}

std::string EnvName(const std::string& flag) {
  return absl::StrCat("SWARMPLAN_", absl::AsciiStrToUpper(absl::StrReplaceAll(flag, {{"-", "_"}})));
}

const Setting* FindSetting(const std::string& flag) {
  for (const Setting& s : Settings()) {
    if (flag == s.flag) return &s;
  }
  return nullptr;
}

}  // namespace

std::string ConfigHelp() {
  std::string help = "swarmplan-server: gRPC path-planning service\n\nFlags (environment):\n";
  const ServerConfig defaults;
  for (const Setting& s : Settings()) {
    absl::StrAppend(&help, "  --", s.flag, " (", EnvName(s.flag), ")\n      ", s.help, "\n");
  }
  return help;
}

absl::StatusOr<ServerConfig> ParseConfig(const std::vector<std::string>& args,
                                         const std::vector<std::string>& environment) {
  ServerConfig config;
  std::map<std::string, std::string> env;
  for (const std::string& e : environment) {
    const size_t eq = e.find('=');
    if (eq != std::string::npos) env[e.substr(0, eq)] = e.substr(eq + 1);
  }
  for (const Setting& s : Settings()) {
    if (auto it = env.find(EnvName(s.flag)); it != env.end()) {
      if (absl::Status st = s.set(config, it->second); !st.ok()) {
        return absl::InvalidArgumentError(
            absl::StrCat(EnvName(s.flag), " (environment): ", st.message()));
      }
    }
  }
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") return absl::NotFoundError(ConfigHelp());
    if (arg.rfind("--", 0) != 0) {
      return absl::InvalidArgumentError(absl::StrCat("unexpected argument '", arg, "'"));
    }
    std::string name = arg.substr(2);
    std::string value;
    if (const size_t eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    } else if (i + 1 < args.size()) {
      value = args[++i];
    } else {
      return absl::InvalidArgumentError(absl::StrCat("--", name, ": missing value"));
    }
    const Setting* setting = FindSetting(name);
    if (setting == nullptr) {
      return absl::InvalidArgumentError(absl::StrCat("unknown flag --", name, " (see --help)"));
    }
    if (absl::Status st = setting->set(config, value); !st.ok()) return st;
  }
  if (config.tls_cert_file.empty() != config.tls_key_file.empty()) {
    return absl::InvalidArgumentError("--tls-cert-file and --tls-key-file go together");
  }
  return config;
}

}  // namespace swarmplan::server
