#pragma once

// The worlds and the runs of the bpso-vertices reproduction: loading or drawing a world with its
// exact optimum, the planner configurations, and running one configuration many times with every
// found path checked.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/experiment.h"
#include "bench/papers/plan_once.h"
#include "core/map/map.h"
#include "core/planner.h"

namespace swarmplan::bench::bpso {

inline constexpr int kVertexCounts[] = {8, 16, 24, 32};

// The shipped world with D vertices was drawn from this seed.
inline uint64_t ShippedWorldSeed(int vertices) { return 4000 + static_cast<uint64_t>(vertices); }

std::string WorldFileName(int vertices);

struct World {
  int vertices = 0;
  std::string name;  // the shipped file, or which drawn world
  MapPtr map;
  double optimum = 0.0;                    // visibility graph: exact shortest path
  std::optional<double> encoding_optimum;  // best ordered vertex subset
};

// A world with its optimum and the best path the encoding can express; INTERNAL when the
// visibility graph finds no path or the encoding beats it.
absl::StatusOr<World> MakeWorld(MapPtr map, int vertices, const std::string& name);

// The shipped world with D = `vertices` from options.worlds_dir.
absl::StatusOr<World> LoadShippedWorld(const ExperimentOptions& options, int vertices);

// The runs of one configuration on one world.
struct Runs {
  int count = 0;
  std::vector<double> lengths;                           // of the found paths
  std::vector<double> seconds;                           // wall time of every run
  std::vector<double> best_iterations;                   // iteration of the final best, found runs
  std::vector<std::vector<IterationStats>> convergence;  // every run
  int found() const { return static_cast<int>(lengths.size()); }
  double success_rate() const { return count == 0 ? 0.0 : static_cast<double>(found()) / count; }
};

// `count` runs with seeds first_seed, first_seed + 1, ...; a found path that is not
// collision-free, does not join start and goal or beats the optimum fails the whole call.
absl::StatusOr<Runs> RunMany(const PlanSpec& spec, const World& world, int count,
                             uint64_t first_seed, const std::string& label, std::ostream* log);

PlanSpec BpsoSpec(int iterations, double swarm_factor, double mutation, bool double_structure);
PlanSpec GaSpec(int generations);

// "1D", "1.5D", "2D".
std::string SwarmLabel(double swarm_factor);

}  // namespace swarmplan::bench::bpso
