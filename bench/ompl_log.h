#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "bench/bench_options.h"
#include "bench/bench_runner.h"
#include "bench/report.h"

namespace swarmplan::bench {

// One problem's runs as an experiment of OMPL's benchmark log format (the grammar of OMPL's
// "How to Benchmark Planners", which ompl_benchmark_statistics.py turns into the Planner Arena
// database): per planner the run properties time, solved, correct solution, solution length,
// solution clearance, optimality ratio, best cost, iterations and evaluations, and each run's
// convergence as the progress properties time, best cost and feasible.
struct OmplExperiment {
  std::string name;
  std::string host;
  std::string date;                // when the experiment started
  std::vector<std::string> setup;  // lines describing the problem
  uint64_t seed = 0;               // the first run's seed
  double time_limit_seconds = 0.0;
  int runs_per_planner = 0;
  double total_seconds = 0.0;
  std::vector<std::string> planners;  // in order; each has runs_per_planner records
  std::vector<RunRecord> records;     // with their convergence
};

void WriteOmplLog(const OmplExperiment& experiment, std::ostream& out);

// One experiment per problem with its records (matched by map and scenario), written to `path`
// for a single problem and to path-1, path-2, ... (the number before the extension) for
// several. Returns the files written; an error names the file that could not be written.
absl::StatusOr<std::vector<std::string>> WriteOmplLogs(const std::string& path,
                                                       const std::vector<BenchProblem>& problems,
                                                       const std::vector<RunRecord>& records,
                                                       const BenchOptions& options,
                                                       absl::Time started, absl::Duration total);

}  // namespace swarmplan::bench
