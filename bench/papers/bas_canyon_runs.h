#pragma once

// The runs of the bas-canyon reproduction: planner configurations (the paper's settings and our
// step options) and what their runs on a canyon measured.

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/bas_canyon_world.h"
#include "bench/papers/comparison.h"
#include "bench/papers/experiment.h"
#include "bench/papers/plan_once.h"

namespace swarmplan::bench::bas {

// A planner configuration with its label in the tables.
struct Row {
  std::string label;
  PlanSpec spec;
};

// What the runs of one row measured. Fitness, lengths and iterations: found paths only.
struct RowRuns {
  int runs = 0;
  std::vector<double> fitness;
  std::vector<double> length;
  std::vector<double> best_iteration;  // 0: the best path is the initial one
  std::vector<double> seconds;         // every run
  int right_branch = 0;                // found paths whose middle waypoint is in the deep branch
  int improved = 0;                    // found paths better than the run's first (iteration > 0)

  SuccessCount found() const { return {static_cast<int>(fitness.size()), runs}; }
  SuccessCount improved_count() const { return {improved, runs}; }
  SuccessCount right_branch_count() const { return {right_branch, runs}; }
};

// The paper's beetle settings (init=paper, every move taken, δ0 = 8 cells, λ1 = λ2 = 0.998,
// c = 2, θ0 = 21 cells), passed explicitly: the planners' defaults are the seeded service ones.
ParamValues PaperBeetleParams(int iterations);
// The paper's ACO: 20 ants.
ParamValues PaperAcoParams(int iterations);
// Our step options on top of the paper's beetle: undo infeasible moves; initial step
// `step_fraction` of the map's ranges instead of δ0 cells.
ParamValues RejectInfeasible(ParamValues params);
ParamValues MapScaledSteps(ParamValues params, double step_fraction);

PlanSpec Spec(const std::string& algorithm, ParamValues params);

// Rows and their runs, looked up by label.
struct RowSet {
  std::vector<Row> rows;
  std::vector<RowRuns> runs;  // as rows
  // nullptr when no row has this label.
  const RowRuns* Find(const std::string& label) const;
};

// The rows of `a` then those of `b`.
RowSet Merged(const RowSet& a, const RowSet& b);

// Runs every row `runs` times on `world` (run i with seed options.seed + i), the (row, run)
// pairs spread over options.jobs threads. Every found path is checked (CheckFoundPath).
absl::StatusOr<RowSet> RunRows(std::vector<Row> rows, const CanyonWorld& world,
                               const ExperimentOptions& options, int runs);

}  // namespace swarmplan::bench::bas
