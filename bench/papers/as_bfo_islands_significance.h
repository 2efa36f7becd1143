#pragma once

// The tests behind the AS-BFO islands report's comparisons: ACO and GA against AS-BFO in each
// cell of Table 4 (optimal runs by Fisher's exact test; lengths, AIN and run times by rank-sum;
// the best and worst runs by a permutation test of the minima and maxima; medians with bootstrap
// 95 % intervals).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bench/papers/as_bfo_islands_report.h"
#include "bench/papers/comparison.h"

namespace swarmplan::bench::as_bfo_islands {

// The runs that reached A*'s optimum, out of all runs.
SuccessCount OptimalCount(const Outcome& outcome, double optimum);

// One method against AS-BFO in one cell of Table 4.
struct MethodTests {
  RankComparison length;            // found paths' lengths
  std::optional<double> optimal_p;  // Fisher on the optimal runs
  bool fewer_optimal = false;       // the method reached the optimum less often
  RankComparison ain;
  RankComparison time;
  std::optional<double> min_p;  // the shortest paths (MinPL), ExtremePermutationP
  std::optional<double> max_p;  // the longest paths (MaxPL)
};
MethodTests TestAgainst(const Outcome& reference, const Outcome& other, double optimum);

// The reference of the tests (AS-BFO) and the methods tested against it (the paper's other
// two), as indices into Methods().
inline constexpr size_t kReferenceMethod = 0;
std::vector<size_t> TestedMethods();

// "S3 20×20", the paper's name of an n x n size.
std::string SizeName(int n);

// The section with a row per cell of Table 4 and method: AS-BFO's medians, then each tested
// method's with its p-values against AS-BFO.
std::string Table4TestsSection(const std::vector<std::vector<World>>& worlds,
                               const Table4& outcomes);

}  // namespace swarmplan::bench::as_bfo_islands
