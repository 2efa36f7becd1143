#pragma once

#include "core/registry.h"

namespace swarmplan {

// `terrain-lattice`: the exact optimum of the terrain planners' objective over the voxel
// lattice of a terrain (terrain_lattice.h), as a registered exact planner of one iteration.
PlannerInfo TerrainLatticeInfo();

}  // namespace swarmplan
