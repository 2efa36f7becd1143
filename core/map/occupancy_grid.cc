#include "core/map/occupancy_grid.h"

#include <algorithm>
#include <cmath>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "core/geometry/distance_transform.h"
#include "core/map/world_range.h"

namespace swarmplan {

absl::StatusOr<OccupancyGrid> OccupancyGrid::Create(int width, int height,
                                                    std::vector<int8_t> cells, double resolution,
                                                    Point2 origin, const MapLimits& limits) {
  if (width <= 0 || height <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("grid size ", width, " x ", height, " must be positive"));
  }
  const int64_t count = static_cast<int64_t>(width) * height;
  if (count > limits.max_cells) {
    return absl::ResourceExhaustedError(absl::StrCat("grid of ", width, " x ", height, " = ", count,
                                                     " cells exceeds the limit of ",
                                                     limits.max_cells, " cells"));
  }
  if (static_cast<int64_t>(cells.size()) != count) {
    return absl::InvalidArgumentError(absl::StrCat("grid of ", width, " x ", height, " needs ",
                                                   count, " cell values, got ", cells.size()));
  }
  if (!std::isfinite(resolution) || resolution <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("resolution must be a positive number, got ", resolution));
  }
  if (absl::Status s =
          CheckRasterInWorldRange(origin, resolution, width, height, "resolution", "grid");
      !s.ok()) {
    return s;
  }
  OccupancyGrid grid;
  grid.width_ = width;
  grid.height_ = height;
  grid.resolution_ = resolution;
  grid.origin_ = origin;
  grid.blocked_.resize(cells.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    const int8_t v = cells[i];
    if (v < kUnknown || v > kOccupied) {
      return absl::InvalidArgumentError(absl::StrCat("cell ", i % width, ",", i / width,
                                                     " has value ", v,
                                                     "; values are -1 (unknown) or 0..100"));
    }
    grid.blocked_[i] = (v == kUnknown || v >= kBlockedThreshold) ? 1 : 0;
    grid.blocked_count_ += grid.blocked_[i];
  }
  grid.cells_ = std::move(cells);
  return grid;
}

const std::vector<double>& OccupancyGrid::ComputeDistanceField() const {
  LazyDistanceField& field = *distance_;
  std::call_once(field.once, [&] {
    field.values = SquaredDistanceTransform(width_, height_, blocked_);
    for (double& d : field.values) d = std::sqrt(d) * resolution_;
    field.ready.store(true, std::memory_order_release);
  });
  return field.values;
}

Cell OccupancyGrid::CellAt(const Point2& p) const {
  const Point2 local = (p - origin_) / resolution_;
  return Cell{static_cast<int>(std::floor(local.x())), static_cast<int>(std::floor(local.y()))};
}

}  // namespace swarmplan
