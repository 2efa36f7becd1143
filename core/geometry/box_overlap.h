#pragma once

#include <vector>

#include "core/map/point.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// Whether an obstacle overlaps the open box (its interior): the per-cell rule of
// RasterizeShapeWorld. Touching only the box's boundary is no overlap.
bool SegmentEntersOpenBox(const Point2& a, const Point2& b, const Bounds2& box);
bool PolygonOverlapsOpenBox(const std::vector<Point2>& polygon, const Bounds2& box);
bool CircleOverlapsOpenBox(const Circle& circle, const Bounds2& box);

}  // namespace swarmplan
