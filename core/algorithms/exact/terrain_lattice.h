#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "core/map/terrain.h"
#include "core/stop_token.h"

namespace swarmplan {

// The voxel lattice of a terrain: a node at every cell centre (i, j) and every height level
// z_k = base + k * step, k = 0..count-1, base = lowest ground + clearance, up to the ceiling. A
// node is usable when it keeps the clearance above the ground (the terrain's collision
// checker). `step` is the vertical_step asked for, or when that is 0 the cell size, coarsened
// so that there are at most max_levels levels.
struct TerrainLatticeLevels {
  double base = 0.0;
  double step = 1.0;
  int count = 0;
};

struct TerrainLatticeOptions {
  double vertical_step = 0.0;  // height units; 0: automatic, see TerrainLatticeLevels
  int max_levels = 64;
  const StopToken* stop = nullptr;  // checked every few thousand expansions
};

// Lattices larger than this (cells x levels) are refused.
inline constexpr int64_t kMaxTerrainLatticeNodes = int64_t{1} << 22;

// INVALID_ARGUMENT for a negative or non-finite vertical_step or max_levels < 2.
absl::StatusOr<TerrainLatticeLevels> MakeTerrainLatticeLevels(const Terrain& terrain,
                                                              double clearance,
                                                              const TerrainLatticeOptions& options);

struct TerrainLatticeResult {
  Path path;          // start, lattice nodes, goal; empty when no lattice path joins them
  double cost = 0.0;  // TerrainPathCost of the path
  int64_t expanded = 0;
  int64_t nodes = 0;  // cells x levels
  TerrainLatticeLevels levels;
  bool stopped = false;
};

// The least-cost path from start to goal (world points) over the lattice with the
// 26-neighbourhood, by A* with an admissible, consistent heuristic. Costs are the terrain
// planners' objective, TerrainSegmentCost (terrain_path_cost.h). An edge is usable when the
// segment keeps the clearance under the ceiling by the terrain's exact collision checker. Start
// and goal join the lattice nodes within one step of them on every axis (|i - x| <= 1,
// |j - y| <= 1 in cell coordinates, |z_k - z| <= step) by collision-checked segments, and each
// other directly when that segment is free. The cost is the lattice optimum: an upper bound on
// the optimum over all paths. FAILED_PRECONDITION when the lowest level is below -cell size
// (the height term could then make a cost negative: the objective counts heights from zero);
// RESOURCE_EXHAUSTED above kMaxTerrainLatticeNodes; INVALID_ARGUMENT for a start or goal
// outside the map's cell-centre rectangle.
absl::StatusOr<TerrainLatticeResult> TerrainLatticeOptimum(const Terrain& terrain,
                                                           const Point3& start, const Point3& goal,
                                                           double clearance,
                                                           const TerrainLatticeOptions& options);

}  // namespace swarmplan
