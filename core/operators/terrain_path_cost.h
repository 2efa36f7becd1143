#pragma once

#include "core/map/point.h"

namespace swarmplan {

// The objective of the terrain planners (seed 000, eq 3) in world units, for any polyline.
// The paper sums, over a path with one waypoint per column, (segment length + Z of the
// segment's end): the height is charged once per column, and a column is one cell of travel
// along x. Read per unit of travel, a segment from a to b costs
//   |b - a| + b.z * |b.x - a.x| / cell_size,
// its length plus the height of its end per cell of x-advance. On a path with one waypoint per
// column this is the paper's fitness exactly (every segment advances one cell in x); a segment
// across x (b.x = a.x) pays its length only. Heights count from the terrain's zero, as in the
// paper: the cost of a segment is >= 0 whenever b.z >= -cell_size.
double TerrainSegmentCost(const Point3& a, const Point3& b, double cell_size);

// The sum of TerrainSegmentCost over consecutive points.
double TerrainPathCost(const Path& path, double cell_size);

}  // namespace swarmplan
