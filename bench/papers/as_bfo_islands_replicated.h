#pragma once

// Table 4 of the AS-BFO reproduction on ten drawn worlds per environment instead of one: per
// world, pooled and paired across worlds, so a difference between methods is told apart from a
// property of one world.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/as_bfo_islands_report.h"
#include "bench/papers/as_bfo_islands_world.h"
#include "bench/papers/experiment.h"
#include "bench/papers/world_replication.h"

namespace swarmplan::bench::as_bfo_islands {

// The environment of world `index` (its first seed ReplicatedWorldSeed(shipped.seed, index));
// index 0 is the shipped environment.
IslandEnvironmentSpec ReplicatedIslandSpec(const IslandEnvironmentSpec& shipped, int index);

// The grids of world `index` at every size of `sizes`, drawn in memory (accepted at every size of
// AsBfoSizes(), as the shipped worlds), and the seed that drew them.
struct DrawnIslandWorld {
  uint64_t first_seed = 0;
  uint64_t seed_drawn = 0;
  std::vector<OccupancyGrid> grids;  // as `sizes`
};
absl::StatusOr<DrawnIslandWorld> DrawReplicatedIslands(const IslandEnvironmentSpec& shipped,
                                                       int index, const std::vector<int>& sizes);

// One drawn world at one size and the runs of every method on it.
struct ReplicatedIslandRuns {
  uint64_t first_seed = 0;
  uint64_t seed_drawn = 0;
  World world;
  std::vector<Outcome> outcomes;  // as `methods`
};

// One environment at one size: its drawn worlds.
struct ReplicatedIslandCell {
  std::string environment;
  int n = 0;
  std::vector<ReplicatedIslandRuns> worlds;
};

// `worlds` worlds of every environment, each method of `methods` (indices into Methods()) run
// `runs` times (seeds options.seed ...) on each at every size of `sizes`.
absl::StatusOr<std::vector<ReplicatedIslandCell>> RunReplicatedIslands(
    const std::vector<size_t>& methods, const std::vector<int>& sizes,
    const ExperimentOptions& options, int worlds, int runs, int max_iterations);

// The report's section: per-world table, pooled table (length / optimum pooled over the worlds,
// rank-sum and Fisher against methods[0]) and the signed-rank test across worlds on the
// per-world medians. `summary` receives the differences the tests support, for the discussion.
std::string ReplicatedIslandsSection(const std::vector<ReplicatedIslandCell>& cells,
                                     const std::vector<size_t>& methods, int runs,
                                     uint64_t first_seed, std::string* summary);

}  // namespace swarmplan::bench::as_bfo_islands
