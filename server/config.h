#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"

namespace swarmplan::server {

// Every setting of the server. Each has a flag (--listen=...) and an environment variable
// (SWARMPLAN_LISTEN=...); the flag wins. See ConfigHelp() for the list.
struct ServerConfig {
  std::string listen = "127.0.0.1:50051";  // host:port; port 0 picks a free one
  int metrics_port = 9464;  // 0 disables the Prometheus endpoint; -1 picks a free port
  std::string metrics_address = "127.0.0.1";
  std::string data_dir = "./swarmplan-data";
  // sqlite:DIR or redis://HOST[:PORT][/DB]; empty: SQLite in data_dir (store_url.h).
  std::string store;
  std::string store_password_file;  // the Redis password, when the server asks for one
  int workers = 0;                  // 0: the number of cores
  int queue_capacity = 64;          // queued (not running) jobs
  // Finished jobs are kept in the store for job_retention, and at most max_retained_jobs of
  // them (the oldest beyond are deleted); job_cache_entries of them are also held in memory.
  absl::Duration job_retention = absl::Hours(24 * 7);
  int max_retained_jobs = 100000;
  int job_cache_entries = 1000;
  // Parsed maps held in memory; the others are parsed from the store when planned on.
  int map_cache_entries = 16;
  absl::Duration shutdown_grace = absl::Seconds(10);
  // With a redis:// store: a running job whose replica stops renewing its lease for this long
  // is taken over by another replica.
  absl::Duration job_lease = absl::Seconds(10);
  // Limits.
  int max_message_bytes = 64 * 1024 * 1024;
  int64_t max_map_cells = 16LL * 1024 * 1024;
  int max_population = 10000;
  int max_iterations = 1000000;
  absl::Duration max_job_time = absl::Minutes(10);
  int max_watchers_per_job = 16;
  // Wall time a worker spends on a job's exact optimum (PlanResult.optimum_length) after the
  // plan; 0 disables it. Optima are cached per map, start, goal and clearance.
  absl::Duration optimum_budget = absl::Seconds(2);
  // A ListMaps/ListJobs page stops before it would exceed this many bytes (or half of
  // max_message_bytes, when smaller).
  int64_t max_page_bytes = 4 * 1024 * 1024;
  // Security: bearer token from a file (empty: off); TLS from certificate and key files.
  std::string token_file;
  std::string tls_cert_file;
  std::string tls_key_file;
  std::string log_level = "info";
};

// Parses flags (argv) over environment variables over defaults. INVALID_ARGUMENT naming the
// flag for an unknown flag or a bad value. `--help` gives NOT_FOUND carrying ConfigHelp().
absl::StatusOr<ServerConfig> ParseConfig(const std::vector<std::string>& args,
                                         const std::vector<std::string>& environment);
std::string ConfigHelp();

}  // namespace swarmplan::server
