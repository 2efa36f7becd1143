#pragma once

#include <vector>

#include "core/map/distance_field.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// The resolution rule of a ShapeWorld's distance field: kShapeFieldCells cells along the longer
// side of the bounds (cell size h = longer side / kShapeFieldCells), plus a ring of
// kShapeFieldRing cells around the bounds, so obstacles just outside the bounds count too. At
// most (256 + 16)^2 cells of 4 bytes: about 300 KB per world, whatever its obstacle count.
inline constexpr int kShapeFieldCells = 256;
inline constexpr int kShapeFieldRing = 8;

// Rasterises the obstacles conservatively (a cell is blocked when its closed square meets a
// circle, holds a piece of a polygon's boundary, or has its centre inside a polygon) and builds
// the signed distance field from that raster. Linear in the cells plus the polygon edges' length
// in cells.
DistanceField ShapeDistanceField(const Bounds2& bounds, const std::vector<Circle>& circles,
                                 const std::vector<Polygon>& polygons);

}  // namespace swarmplan
