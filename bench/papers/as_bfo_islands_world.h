#pragma once

// The island worlds of the AS-BFO reproduction: one continuous sea with island-shaped obstacles,
// grid partitioned at several sizes with the same obstacle ratio (the paper's S1..S5), start and
// goal in opposite corners.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/occupancy_grid.h"
#include "core/map/point.h"

namespace swarmplan::bench {

// How one environment's islands are drawn. Coordinates are in the unit square.
struct IslandEnvironmentSpec {
  std::string name;  // file name prefix, e.g. "env1"
  uint64_t seed = 1;
  int islands = 5;
  double min_radius = 0.08;  // radius of an island's main disc
  double max_radius = 0.14;
  double obstacle_ratio = 0.25;  // blocked share of every size: exactly round(ratio * n * n)
};

// A disc of an island, in the unit square.
struct IslandDisc {
  Point2 centre;
  double radius = 0.0;
};

// The islands of an environment that pass the checks at every size in `sizes`, and the seed
// that drew them (spec.seed, or the first following seed whose islands pass).
struct IslandLayout {
  std::vector<IslandDisc> discs;
  uint64_t seed = 0;
};

// The paper's two environments and five sizes (S1..S5).
const std::vector<IslandEnvironmentSpec>& AsBfoEnvironments();
const std::vector<int>& AsBfoSizes();

// Start and goal of an n x n world: opposite corners (0, 0) and (n - 1, n - 1).
Cell IslandStart(int n);
Cell IslandGoal(int n);

// Islands drawn from `seed`: each a main disc (radius uniform in [min, max]) with 2-4 lobes
// overlapping it, so every island is one connected blob; centres keep away from the corners.
std::vector<IslandDisc> DrawIslands(const IslandEnvironmentSpec& spec, uint64_t seed);

// The n x n grid of the islands: the round(ratio * n * n) cells whose centres lie deepest inside
// the islands (largest radius - distance to a disc centre; ties by row-major index) are blocked,
// never the start or goal cell. Row y of the grid is line y of its ASCII file.
absl::StatusOr<OccupancyGrid> RasteriseIslands(const std::vector<IslandDisc>& discs, int n,
                                               double obstacle_ratio);

// Draws islands from spec.seed, spec.seed + 1, ... until at every size start and goal are
// connected (8-connected, no corner cutting) and the straight diagonal between them is blocked;
// FAILED_PRECONDITION after 1000 tries.
absl::StatusOr<IslandLayout> AcceptedIslands(const IslandEnvironmentSpec& spec,
                                             const std::vector<int>& sizes);

// Islands of a grid: the 8-connected components of its blocked cells.
int CountIslands(const OccupancyGrid& grid);

// File name of an environment at a size, e.g. "env1-10x10.txt".
std::string IslandWorldFile(const std::string& environment, int n);

}  // namespace swarmplan::bench
