#pragma once

#include <optional>
#include <vector>

#include "core/geometry/collision.h"
#include "core/map/occupancy_grid.h"
#include "core/map/point.h"

namespace swarmplan {

// A path that keeps `clearance` (world units, > 0) by the map's exact checker, made from a
// path that may come closer (the shortest path on ClearanceGrid's lower bound, say). Every
// vertex moves straight away from the nearest blocked square until it keeps the clearance with
// a margin of 1e-3 of it; a segment that still comes too close is split where it comes closest,
// that point moved the same way, until every piece keeps the clearance; then each kept point
// joins the last of the points after it that it sees one after another. `vertices` are world
// points from the start to the goal, which stay where they are. None when that does not give a
// path (where the path passes, the clearance does not fit with the margin).
std::optional<std::vector<Point2>> RepairToClearance(const OccupancyGrid& grid,
                                                     const CollisionChecker& exact,
                                                     const std::vector<Point2>& vertices,
                                                     double clearance);

}  // namespace swarmplan
