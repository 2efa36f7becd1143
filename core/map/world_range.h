#pragma once

#include "absl/status/status.h"
#include "core/map/limits.h"
#include "core/map/point.h"

namespace swarmplan {

// A raster of `columns` x `rows` cells of `cell` world units from `origin` lies within
// +-kMaxWorldCoordinate; otherwise INVALID_ARGUMENT naming the origin or `cell_name`
// ("resolution", "cell size") and the map kind (`what`: "grid", "terrain").
absl::Status CheckRasterInWorldRange(const Point2& origin, double cell, int columns, int rows,
                                     const char* cell_name, const char* what);

}  // namespace swarmplan
