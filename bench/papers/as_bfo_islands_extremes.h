#pragma once

// A test for the best and worst single runs (MinPL and MaxPL of the paper's Table 4): whether the
// minimum (or maximum) of one planner's runs differs from another's by more than relabelling the
// runs at random explains.

#include <cstdint>
#include <optional>
#include <vector>

namespace swarmplan::bench::as_bfo_islands {

enum class Extreme { kMin, kMax };

// A two-sided Monte Carlo permutation test of |extreme(a) − extreme(b)|: the pooled runs are split
// at random into samples of a's and b's sizes `permutations` times (a generator seeded with
// `seed`), and p = (1 + the splits whose difference is at least the observed one) /
// (1 + permutations), a valid p-value for any number of splits. nullopt when a sample is empty
// or permutations < 1.
inline constexpr int kExtremePermutations = 9999;
std::optional<double> ExtremePermutationP(const std::vector<double>& a,
                                          const std::vector<double>& b, Extreme extreme,
                                          int permutations = kExtremePermutations,
                                          uint64_t seed = 1);

}  // namespace swarmplan::bench::as_bfo_islands
