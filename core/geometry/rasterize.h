#pragma once

#include "absl/status/statusor.h"
#include "core/map/limits.h"
#include "core/map/occupancy_grid.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// An occupancy grid of the world at `resolution` (world units per cell), origin at the bounds'
// minimum corner. The grid has floor(width / resolution) x floor(height / resolution) cells
// (a dimension within 1e-9 of a whole number of cells is rounded), so it never covers space
// outside the bounds. A cell is occupied when its open square overlaps an obstacle: any cell
// with a part inside an obstacle is blocked; a cell that only touches an obstacle's boundary
// stays free. So a grid path that touches no blocked cell touches no obstacle interior.
absl::StatusOr<OccupancyGrid> RasterizeShapeWorld(const ShapeWorld& world, double resolution,
                                                  const MapLimits& limits = {});

}  // namespace swarmplan
