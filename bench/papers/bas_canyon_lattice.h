#pragma once

// A yardstick for the BAS terrain model: the best path whose interior waypoints lie on a (Y, Z)
// lattice, by dynamic programming over the columns. Its fitness bounds the true optimum of the
// model from above (a finer lattice can only do better).

#include "absl/status/statusor.h"
#include "core/map/point.h"
#include "core/problem.h"

namespace swarmplan::bench {

struct LatticeOptions {
  double y_step = 0.5;   // Y values 0, y_step, ... up to depth - 1
  double z_step = 0.25;  // Z values lowest ground, + z_step, ... up to z_max
  double max_dy = 4.0;   // largest |Y change| between consecutive waypoints
  // Waypoints fly at most this far above the highest ground.
  double max_above_highest_ground = 1.0;
};

struct LatticePath {
  Path path;  // start, one waypoint per column, goal
  double fitness = 0.0;
};

// The lowest fitness (eq 3, as TerrainObjective: sum of segment length + Z of the segment's end)
// over lattice paths whose every segment keeps the problem's clearance. INVALID_ARGUMENT as
// TerrainObjective::Create; NOT_FOUND when no lattice path is feasible.
absl::StatusOr<LatticePath> LatticeOptimum(const Problem& problem,
                                           const LatticeOptions& options = {});

}  // namespace swarmplan::bench
