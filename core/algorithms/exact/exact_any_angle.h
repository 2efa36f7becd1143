#pragma once

#include "core/registry.h"

namespace swarmplan {

// `exact-any-angle`: the Euclidean shortest path among the blocked cells of an occupancy grid
// (Anya, AnyAngleSearch), offset off the corners it wraps so that it is collision-free.
PlannerInfo ExactAnyAngleInfo();

}  // namespace swarmplan
