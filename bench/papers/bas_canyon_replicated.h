#pragma once

// The bas-canyon comparisons on kReplicatedWorlds canyons from the same generator (world 0 the
// shipped one): fitness over each world's lattice optimum per world and pooled, and the
// signed-rank test of the per-world medians for the paper's headline pairs.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/bas_canyon_runs.h"
#include "bench/papers/bas_canyon_significance.h"
#include "bench/papers/experiment.h"

namespace swarmplan::bench::bas {

struct ReplicatedWorld {
  int index = 0;
  uint64_t seed = 0;
  double optimum = 0.0;  // the lattice yardstick's fitness
  RowSet set;
  RowSet ratios;  // as set, fitness divided by optimum
};

// `worlds` canyons (drawn in memory over options.jobs threads), every row run `runs` times on
// each.
absl::StatusOr<std::vector<ReplicatedWorld>> RunReplicatedCanyons(const std::vector<Row>& rows,
                                                                  const ExperimentOptions& options,
                                                                  int worlds, int runs,
                                                                  double lattice_vertical_step);

struct ReplicatedPairTest {
  ClaimedPair pair;
  RankComparison pooled;                      // rank-sum on pooled fitness / optimum
  std::optional<double> pooled_found_p;       // Fisher on the pooled found runs
  SuccessCount reference_found, other_found;  // pooled
  std::optional<double> signed_rank_p;        // per-world medians of fitness / optimum
  int worlds_other_lower = 0;
  int worlds = 0;
  bool supported() const { return Significant(signed_rank_p) && 2 * worlds_other_lower > worlds; }
  bool contradicted() const {
    return Significant(signed_rank_p) && 2 * worlds_other_lower < worlds;
  }
};

std::vector<ReplicatedPairTest> TestReplicatedPairs(const std::vector<ReplicatedWorld>& worlds,
                                                    const std::vector<ClaimedPair>& pairs);

// Per-world medians, the pooled table and the pairs' tests.
std::string ReplicatedSection(const std::vector<ReplicatedWorld>& worlds,
                              const std::vector<ReplicatedPairTest>& tests);

}  // namespace swarmplan::bench::bas
