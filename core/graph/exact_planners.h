#pragma once

#include "core/registry.h"

namespace swarmplan {

// The exact reference planners as registered planners: `astar`, `dijkstra` and `theta-star` on
// occupancy grids, `visibility-graph` on shape worlds, `terrain-lattice` on terrain. Each runs its
// search once and reports it as a single iteration. Declared also in core/algorithms/register.h.
void RegisterExactPlanners(Registry& registry);

}  // namespace swarmplan
