#pragma once

#include "core/registry.h"

namespace swarmplan {

// The bat algorithm over spline waypoints, the baseline of the AEM-BSO paper: ba.
PlannerInfo BatInfo();

}  // namespace swarmplan
