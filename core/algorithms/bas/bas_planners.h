#pragma once

#include "core/registry.h"

namespace swarmplan {

// The beetle antennae family of the 3D BAS paper (terrain, and spline waypoints on 2D maps) and
// its ACO baseline on terrain.
PlannerInfo BasInfo();
PlannerInfo LfsBasInfo();
PlannerInfo AcoBasInfo();
PlannerInfo SioBasInfo();
PlannerInfo MultiBasInfo();
PlannerInfo TerrainAcoInfo();  // "aco"

}  // namespace swarmplan
