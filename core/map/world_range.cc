#include "core/map/world_range.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"

namespace swarmplan {

absl::Status CheckRasterInWorldRange(const Point2& origin, double cell, int columns, int rows,
                                     const char* cell_name, const char* what) {
  if (!InWorldRange(origin.x()) || !InWorldRange(origin.y())) {
    return absl::InvalidArgumentError(
        absl::StrCat("origin must be finite and within +-", kMaxWorldCoordinate));
  }
  if (!InWorldRange(std::max(std::abs(origin.x()), std::abs(origin.y())) +
                    cell * std::max(columns, rows))) {
    return absl::InvalidArgumentError(absl::StrCat(cell_name, " ", cell, ": the ", what,
                                                   " would reach beyond +-", kMaxWorldCoordinate));
  }
  return absl::OkStatus();
}

}  // namespace swarmplan
