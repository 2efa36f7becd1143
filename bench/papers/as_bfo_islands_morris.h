#pragma once

// The Morris sensitivity analysis of the AS-BFO paper's section 4.2: P, Nc, Nre and Ned over the
// ranges of its Table 1, r trajectories on a 4-level grid, each sample run 10 times (its Table
// 3) for the average path length (its output) and the AIN (ours), and μ, μ*, σ per parameter.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/as_bfo_islands_report.h"
#include "bench/papers/morris.h"

namespace swarmplan::bench::as_bfo_islands {

struct MorrisFactor {
  std::string parameter;  // registered name
  std::string symbol;     // the paper's
  int low = 0;            // the paper's range (its Table 1)
  int high = 0;
};
const std::vector<MorrisFactor>& MorrisFactors();

inline constexpr int kMorrisLevels = 4;
inline constexpr int kMorrisTrajectories = 10;  // the paper's r = 4 is too few to rank four
inline constexpr int kPaperMorrisTrajectories = 4;
inline constexpr int kMorrisRuns = 10;  // runs per sample, the paper's
inline constexpr int kQuickMorrisTrajectories = 2;

// A grid coordinate x in [0, 1] as the factor's value: low + x (high − low), rounded.
int MorrisValue(const MorrisFactor& factor, double x);

// The analysis on one world.
struct MorrisAnalysis {
  const World* world = nullptr;
  std::vector<MorrisTrajectory> design;
  std::vector<std::vector<Outcome>> outcomes;  // [trajectory][point]
  MorrisIndices apl;
  MorrisIndices ain;
};

// The design drawn from `seed`; every sample runs `runs` times (seeds seed … seed + runs − 1)
// with wandering initial paths, spread over `jobs` threads (the result does not depend on it).
absl::StatusOr<MorrisAnalysis> RunMorris(const World& world, int trajectories, int runs,
                                         int max_iterations, uint64_t seed, int jobs);

// The factors ranked by μ* of `indices`, highest first.
std::vector<size_t> RankByMuStar(const MorrisIndices& indices);

std::string MorrisSection(const std::vector<MorrisAnalysis>& analyses, int runs, uint64_t seed);

// The discussion's paragraph: our ranking against the paper's (Nre and Ned most important).
std::string MorrisParagraph(const std::vector<MorrisAnalysis>& analyses);

}  // namespace swarmplan::bench::as_bfo_islands
