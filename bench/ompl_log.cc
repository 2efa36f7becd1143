#include "bench/ompl_log.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_replace.h"

namespace swarmplan::bench {
namespace {

// A measurement: a number, "inf", "nan", or nothing when unknown.
std::string Data(std::optional<double> value) {
  if (!value) return "";
  if (std::isnan(*value)) return "nan";
  if (std::isinf(*value)) return *value > 0 ? "inf" : "";  // the format has no -inf
  return absl::StrFormat("%.17g", *value);
}

std::string Flag(bool value) { return value ? "1" : "0"; }

void WritePlanner(const std::string& planner, const std::vector<const RunRecord*>& runs,
                  std::ostream& out) {
  out << planner << "\n0 common properties\n";
  const char* run_properties[] = {"time REAL",
                                  "solved BOOLEAN",
                                  "correct solution BOOLEAN",
                                  "solution length REAL",
                                  "solution clearance REAL",
                                  "optimality ratio REAL",
                                  "best cost REAL",
                                  "iterations INTEGER",
                                  "evaluations INTEGER"};
  out << std::size(run_properties) << " properties for each run\n";
  for (const char* property : run_properties) out << property << "\n";
  out << runs.size() << " runs\n";
  for (const RunRecord* r : runs) {
    const bool solved = r->length.has_value();
    const std::string fields[] = {Data(r->wall_seconds),
                                  Flag(solved),
                                  solved ? Flag(r->success) : "",
                                  Data(r->length),
                                  Data(r->min_clearance),
                                  Data(r->ratio),
                                  Data(r->fitness),
                                  absl::StrCat(r->iterations),
                                  absl::StrCat(r->evaluations)};
    for (const std::string& field : fields) out << field << "; ";
    out << "\n";
  }
  out << "3 progress properties for each run\ntime REAL\nbest cost REAL\nfeasible BOOLEAN\n";
  out << runs.size() << " runs\n";
  for (const RunRecord* r : runs) {
    if (r->convergence.empty()) {  // the plan failed before its first iteration
      out << Data(r->wall_seconds) << ",," << Flag(false) << ",\n";
      continue;
    }
    for (size_t i = 0; i < r->convergence.size(); ++i) {
      const RunRecord::Progress& p = r->convergence[i];
      if (i > 0) out << ";";
      out << Data(p.seconds) << "," << Data(p.best_fitness) << "," << Flag(p.feasible) << ",";
    }
    out << "\n";
  }
  out << ".\n";
}

}  // namespace

void WriteOmplLog(const OmplExperiment& e, std::ostream& out) {
  out << "Experiment " << e.name << "\n";
  out << "Running on " << e.host << "\n";
  out << "Starting at " << e.date << "\n";
  out << "<<<|\n";
  for (const std::string& line : e.setup) out << line << "\n";
  out << "|>>>\n";
  out << e.seed << " is the random seed\n";
  out << Data(e.time_limit_seconds) << " seconds per run\n";
  out << "0 MB per run\n";
  out << e.runs_per_planner << " runs per planner\n";
  out << Data(e.total_seconds) << " seconds spent to collect the data\n";
  out << e.planners.size() << " planners\n";
  for (const std::string& planner : e.planners) {
    std::vector<const RunRecord*> runs;
    for (const RunRecord& r : e.records) {
      if (r.planner == planner) runs.push_back(&r);
    }
    WritePlanner(planner, runs, out);
  }
}

namespace {

std::string WithoutSpaces(const std::string& text) {
  return absl::StrReplaceAll(text, {{" ", "_"}, {"\t", "_"}});
}

std::string HostName() {
  char host[256] = {};
  if (gethostname(host, sizeof(host) - 1) != 0 || host[0] == '\0') return "unknown";
  return WithoutSpaces(host);
}

// path-N: the number before the extension of the file name.
std::string Numbered(const std::string& path, size_t n) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
    return absl::StrCat(path, "-", n);
  }
  return absl::StrCat(path.substr(0, dot), "-", n, path.substr(dot));
}

std::string PointText(const Point3& p) {
  return absl::StrFormat("%.17g %.17g %.17g", p.x(), p.y(), p.z());
}

}  // namespace

absl::StatusOr<std::vector<std::string>> WriteOmplLogs(const std::string& path,
                                                       const std::vector<BenchProblem>& problems,
                                                       const std::vector<RunRecord>& records,
                                                       const BenchOptions& options,
                                                       absl::Time started, absl::Duration total) {
  std::vector<std::string> written;
  for (size_t i = 0; i < problems.size(); ++i) {
    const BenchProblem& problem = problems[i];
    OmplExperiment e;
    e.name = WithoutSpaces(absl::StrCat(problem.map_name, "_", problem.scenario));
    e.host = HostName();
    e.date = absl::FormatTime("%Y-%m-%dT%H:%M:%SZ", started, absl::UTCTimeZone());
    e.setup = {absl::StrCat("map ", problem.map_name),
               absl::StrCat("scenario ", problem.scenario),
               absl::StrCat("start ", PointText(problem.start)),
               absl::StrCat("goal ", PointText(problem.goal)),
               absl::StrCat("clearance ", options.clearance),
               absl::StrCat("smoothing ", options.smoothing),
               problem.optimal ? absl::StrFormat("exact optimum %.17g", *problem.optimal)
                               : absl::StrCat("exact optimum unknown: ", problem.optimum_note)};
    e.seed = options.seed;
    e.time_limit_seconds = options.time_budget_seconds.value_or(0.0);
    e.runs_per_planner = options.runs;
    e.total_seconds = absl::ToDoubleSeconds(total);
    for (const RunRecord& r : records) {
      if (r.map != problem.map_name || r.scenario != problem.scenario) continue;
      if (std::find(e.planners.begin(), e.planners.end(), r.planner) == e.planners.end()) {
        e.planners.push_back(r.planner);
      }
      e.records.push_back(r);
    }
    const std::string file = problems.size() == 1 ? path : Numbered(path, i + 1);
    std::ofstream out(file);
    WriteOmplLog(e, out);
    out.close();
    if (!out) return absl::UnavailableError(absl::StrCat("cannot write ", file));
    written.push_back(file);
  }
  return written;
}

}  // namespace swarmplan::bench
