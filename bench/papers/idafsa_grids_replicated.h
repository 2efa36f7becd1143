#pragma once

// The IDAFSA reproduction's planners on ten drawn worlds per grid size instead of one: per world,
// pooled and paired across worlds, so a difference between planners is told apart from a
// property of one world.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/experiment.h"
#include "bench/papers/idafsa_grids_runs.h"
#include "bench/papers/idafsa_grids_significance.h"
#include "bench/papers/idafsa_grids_worlds.h"
#include "bench/papers/world_replication.h"

namespace swarmplan::bench {

// World `index` of the grid size of `shipped`; index 0 is the shipped world's spec.
IdafsaGridWorld ReplicatedIdafsaWorld(const IdafsaGridWorld& shipped, int index);

// One drawn world and the runs of every configuration on it.
struct ReplicatedIdafsaWorldRuns {
  IdafsaGridWorld spec;
  uint64_t seed_drawn = 0;
  int blocked = 0;
  double optimum = 0.0;               // the shortest path of segment-checked 24-neighbourhood moves
  double theta_star = 0.0;            // Theta*'s any-angle path
  std::vector<FishRunStats> configs;  // as the configurations
};

struct ReplicatedIdafsaGrid {
  int size = 0;
  std::vector<ReplicatedIdafsaWorldRuns> worlds;
};

// `worlds` worlds of the grid size of `shipped`, drawn in memory, each configuration run `runs`
// times (seeds options.seed ... options.seed + runs - 1) for `generations` generations on each.
absl::StatusOr<ReplicatedIdafsaGrid> RunReplicatedIdafsaGrid(const IdafsaGridWorld& shipped,
                                                             const std::vector<FishConfig>& configs,
                                                             const ExperimentOptions& options,
                                                             int worlds, int runs, int generations);

// The paper's claims for configs[reference] (idafsa) against the other configurations: on the
// runs pooled over the worlds (shorter paths, fewer turning points, higher success), and paired
// across worlds by the signed-rank test on the per-world medians and success rates (shorter
// paths, higher success).
std::vector<ClaimTests> PooledClaims(const ReplicatedIdafsaGrid& grid,
                                     const std::vector<FishConfig>& configs, size_t reference);
std::vector<ClaimTests> AcrossWorldClaims(const ReplicatedIdafsaGrid& grid,
                                          const std::vector<FishConfig>& configs, size_t reference);

// The report's section: per grid size a per-world table, a pooled table (length over each
// world's optimum) and the signed-rank test of the per-world medians, each configuration against
// configs[reference]. `summary` receives the conclusions the tests support, for the discussion.
std::string ReplicatedIdafsaSection(const std::vector<ReplicatedIdafsaGrid>& grids,
                                    const std::vector<FishConfig>& configs, size_t reference,
                                    int runs, std::string* summary);

}  // namespace swarmplan::bench
