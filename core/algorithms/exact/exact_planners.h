#pragma once

#include "core/registry.h"

namespace swarmplan {

// The exact reference planners: `astar`, `dijkstra` and `theta-star` on occupancy grids,
// `visibility-graph` on shape worlds. Each runs its search once and reports it as a single
// iteration.
PlannerInfo AStarInfo();
PlannerInfo DijkstraInfo();
PlannerInfo ThetaStarInfo();
PlannerInfo VisibilityGraphInfo();

}  // namespace swarmplan
