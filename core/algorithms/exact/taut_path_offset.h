#pragma once

#include <vector>

#include "absl/status/statusor.h"
#include "core/map/occupancy_grid.h"
#include "core/map/point.h"

namespace swarmplan {

// A collision-free polyline near a shortest path that touches blocked cells. `vertices` are in
// grid coordinates ((world - origin) / resolution) and form a path that may touch the closed
// squares of blocked cells (at its corners, or grazing lattice points and edges) but never
// crosses them. Every lattice point where the path touches a blocked cell becomes a vertex and
// moves `offset` cells (per axis) away from the blocked cells around it; the ends stay. The
// result touches no blocked cell (GridCollisionChecker::TraversalFree on every segment) and
// is longer by at most 3 * offset per vertex. Internal error when that cannot be achieved (a
// path that crosses a blocked cell).
absl::StatusOr<std::vector<Point2>> OffsetTautPath(const OccupancyGrid& grid,
                                                   const std::vector<Point2>& vertices,
                                                   double offset);

}  // namespace swarmplan
