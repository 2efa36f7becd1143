#pragma once

// The runs of the AEM-BSO Table 1 reproduction: one optimiser configuration on one test
// function, many seeds, each result checked.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/aem_bso_test_functions.h"
#include "bench/papers/experiment.h"
#include "core/params.h"

namespace swarmplan::bench::aem_bso {

// A registered swarm planner's optimiser with some parameters changed from its defaults, run
// for `iteration_factor` times the table's iterations (for equal evaluation budgets).
struct OptimiserConfig {
  std::string label;  // the report's column, e.g. "PSO"
  std::string planner_id;
  ParamValues overrides;
  int iteration_factor = 1;
};

// One table cell to run: a configuration on a function (shifted off the origin or not).
struct FunctionJob {
  OptimiserConfig config;
  const TestFunction* function = nullptr;
  int dim = 30;
  bool shifted = false;
  int runs = 0;
};

// The iterations (1-based) after which a run's best so far is kept: 1 %, 5 %, 10 %, 25 % and
// 50 % of `t_max` and the end, without repeats or zeros.
std::vector<int> ConvergenceCheckpoints(int t_max);

// The final best value of every run, its best so far at the checkpoints, and the cost.
struct FunctionCell {
  std::vector<double> best_values;
  // best_so_far[k][r]: run r's best value after ConvergenceCheckpoints(t_max)[k] iterations.
  std::vector<std::vector<double>> best_so_far;
  double evaluations_per_run = 0.0;
  double seconds = 0.0;  // wall time of all runs
};

// The shift of the origin-bias check: o_j = +-shift_fraction * upper, alternating in sign.
Eigen::VectorXd ShiftFor(const TestFunction& function, int dim, double shift_fraction);
inline constexpr double kShiftFraction = 0.2;

// Runs every job (run r of a job with seed `seed + r`, `iterations * iteration_factor`
// iterations, `population` individuals) on options.jobs threads; the cells are in the jobs'
// order. INTERNAL when an optimiser reports a result that is not real (CheckOptimiserResult).
absl::StatusOr<std::vector<FunctionCell>> RunFunctionJobs(const std::vector<FunctionJob>& jobs,
                                                          int iterations, int population,
                                                          uint64_t seed,
                                                          const ExperimentOptions& options);

}  // namespace swarmplan::bench::aem_bso
