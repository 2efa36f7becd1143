#pragma once

#include <string>

#include "absl/time/time.h"
#include "core/problem.h"
#include "core/registry.h"
#include "core/stop_token.h"

namespace swarmplan {

// The yardstick of a plan: the exact optimum for the problem, found by the exact planner of the
// map's kind (ExactPlannerFor), or the reason it is not known.
struct Optimum {
  bool known = false;
  double length = 0.0;  // of the exact path, world units; valid when known
  double cost = 0.0;    // PlanCost of the exact path: the length on 2D maps
  std::string planner;  // the exact planner that was asked
  std::string reason;   // when not known, for a person: "no path", "over the budget of 2s", ...
};

// The exact planner of each map kind: `exact-any-angle` on occupancy grids (the Euclidean
// shortest path among the blocked cells; with a clearance, the best of the optimum on sub-cells
// that keep it and the lower bound's path moved off the walls: an upper bound, see
// ExactAnyAngleInfo), `visibility-graph` on shape worlds, `terrain-lattice` on terrain (the optimum
// on the voxel lattice, an upper bound on the continuous one).
const char* ExactPlannerFor(MapKind kind);

// Runs the exact planner of the problem's map kind with its default parameters, for at most
// `budget` of wall time and until `stop` trips. Never fails: what went wrong is the reason.
Optimum ComputeOptimum(const Registry& registry, const Problem& problem, absl::Duration budget,
                       const StopToken& stop = StopToken());

// What the exact planner of the map's kind minimises: the length on 2D maps, the terrain
// objective of the terrain planners (TerrainPathCost, world units) on terrain.
double PlanCost(const Map& map, const Path& path);

// cost / optimum.cost, or 0 when the optimum is not known or costs 0.
double OptimalityRatio(double cost, const Optimum& optimum);

}  // namespace swarmplan
