#pragma once

// Table 3 of the AEM-BSO reproduction on ten drawn worlds per environment instead of one: per
// world and pooled, so a difference between planners is told apart from a property of one
// world.

#include <map>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/aem_bso_worlds_generate.h"
#include "bench/papers/aem_bso_worlds_runs.h"
#include "bench/papers/experiment.h"
#include "bench/papers/world_replication.h"

namespace swarmplan::bench::aem_bso {

// World `index` of the environment `spec` (its first seed ReplicatedWorldSeed(spec.seed, index));
// index 0 is the shipped world.
AemBsoWorldSpec ReplicatedSpec(const AemBsoWorldSpec& spec, int index);

struct ReplicatedWorld {
  AemBsoWorldSpec spec;
  double optimum = 0.0;
  std::map<std::string, CellStats> cells;  // planner -> its runs with the spline
};

struct ReplicatedEnvironment {
  std::string name;  // "simple", "complex"
  std::vector<ReplicatedWorld> worlds;
};

// `worlds` worlds of the environment, each planner of `planners` run `runs` times with the
// spline on each, as the paper's Table 3.
absl::StatusOr<ReplicatedEnvironment> RunReplicatedEnvironment(
    const AemBsoWorldSpec& spec, const std::vector<std::string>& planners,
    const ExperimentOptions& options, int worlds, int runs, int iterations);

// The report's section: per-world and pooled tables, each planner against `reference`
// (pooled: Fisher's exact test on the found runs, rank-sum on length / optimum; across worlds:
// the signed-rank test on the per-world medians of z / optimum). `summary` receives the
// differences the tests support, per environment, for the discussion.
std::string ReplicatedSection(const std::vector<ReplicatedEnvironment>& environments,
                              const std::vector<std::string>& planners,
                              const std::string& reference, int runs, uint64_t first_seed,
                              std::string* summary);

}  // namespace swarmplan::bench::aem_bso
