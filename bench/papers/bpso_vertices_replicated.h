#pragma once

// The main comparisons of the bpso-vertices reproduction (Table 1's N = 1D against 2D, and the
// paper's mutation against none) on ten drawn worlds per vertex count instead of one: per world,
// pooled and paired across worlds, so a difference between configurations is told apart from a
// property of one world.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/bpso_vertices_runs.h"
#include "bench/papers/experiment.h"
#include "bench/papers/world_replication.h"
#include "core/map/shape_world.h"

namespace swarmplan::bench::bpso {

// World `index` with D = `vertices` (drawn from ReplicatedWorldSeed(ShippedWorldSeed(D), index));
// index 0 is the shipped world.
uint64_t ReplicatedBpsoWorldSeed(int vertices, int index);
absl::StatusOr<ShapeWorld> DrawReplicatedBpsoWorld(int vertices, int index);

struct ReplicatedConfig {
  std::string label;
  double swarm_factor;
  double mutation;
};
// The configurations every drawn world runs, the first of each pair of ReplicatedPairs being the
// reference.
const std::vector<ReplicatedConfig>& ReplicatedConfigs();
struct ReplicatedPair {
  size_t reference;
  size_t other;
  std::string claim;  // the paper's, for the other against the reference
};
const std::vector<ReplicatedPair>& ReplicatedPairs();

struct ReplicatedWorldRuns {
  int index = 0;
  uint64_t seed = 0;
  double optimum = 0.0;
  std::vector<Runs> configs;  // as ReplicatedConfigs
};
struct ReplicatedVertexCount {
  int vertices = 0;
  std::vector<ReplicatedWorldRuns> worlds;
};

// `worlds` worlds per vertex count of kVertexCounts, drawn in memory, each configuration run
// `runs` times (seeds options.seed ...) for `iterations` iterations on each; the worlds are
// spread over options.jobs threads.
absl::StatusOr<std::vector<ReplicatedVertexCount>> RunReplicatedBpsoWorlds(
    const ExperimentOptions& options, int worlds, int runs, int iterations);

// The report's section: per-world table, pooled table (rank-sum on length / optimum, Fisher on
// the found runs, rank-sum on the iteration of the final best) and the signed-rank test of the
// per-world medians, per vertex count and over all of them.
std::string ReplicatedBpsoSection(const std::vector<ReplicatedVertexCount>& counts, int runs,
                                  uint64_t first_seed);

// Discussion items: per pair, the differences the tests support and whether they support the
// paper's claim.
std::string ReplicatedBpsoSummary(const std::vector<ReplicatedVertexCount>& counts);

}  // namespace swarmplan::bench::bpso
