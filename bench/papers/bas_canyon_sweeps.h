#pragma once

// The paper's Table 3 (the four planners at several iteration counts, 10 runs each) and Fig. 6
// (LFS-BAS and ACO-BAS from a start moved toward the canyon's shallow left side).

#include <string>
#include <vector>

#include "bench/papers/bas_canyon_runs.h"
#include "bench/papers/bas_canyon_significance.h"

namespace swarmplan::bench::bas {

// aco, bas, lfs-bas and aco-bas with the paper's settings at each iteration count, labelled
// "<planner>, <n> iterations".
std::vector<Row> IterationSweepRows(const std::vector<int>& iterations);
// Per planner: the fewest iterations against the most (does more iterations lower the fitness?)
// and the second most against the most (has it converged?).
std::vector<ClaimedPair> IterationSweepPairs(const std::vector<int>& iterations);
// The iteration counts of a run: the paper's, or a few for quick runs.
std::vector<int> SweepIterations(bool quick);

// Fig. 6's start: the first column, left_bulge rows left of the mouth (on the slope toward the
// shallow left side); the goal stays at the mouth.
double MovedStartY();
// lfs-bas and aco-bas with the paper's settings, labelled "<planner>, moved start".
std::vector<Row> MovedStartRows(int iterations);

// Fig. 6's claim on the deep-branch counts: Fisher's p of lfs-bas against aco-bas, and the
// verdict "lfs-bas finds the deep branch more often".
struct MovedStartTest {
  SuccessCount lfs_right;
  SuccessCount aco_bas_right;
  std::optional<double> p;
  bool supported() const { return Significant(p) && lfs_right.rate() > aco_bas_right.rate(); }
};
MovedStartTest TestMovedStart(const RowSet& set);

}  // namespace swarmplan::bench::bas
