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
  // Checked, then converted, in loops without an exit per cell, which the compiler vectorises:
  // subdivided grids of the exact planners have millions of cells.
  const size_t n = cells.size();
  const int8_t* v = cells.data();
  // Valid values are -1..100, i.e. v + 1 in 0..101 as an unsigned byte.
  uint8_t largest = 0;
  for (size_t i = 0; i < n; ++i) largest = std::max(largest, static_cast<uint8_t>(v[i] + 1));
  if (largest > kOccupied + 1) {
    const size_t i =
        static_cast<size_t>(std::find_if(cells.begin(), cells.end(),
                                         [](int8_t c) { return c < kUnknown || c > kOccupied; }) -
                            cells.begin());
    return absl::InvalidArgumentError(absl::StrCat("cell ", i % width, ",", i / width,
                                                   " has value ", cells[i],
                                                   "; values are -1 (unknown) or 0..100"));
  }
  grid.blocked_.resize(n);
  uint8_t* blocked = grid.blocked_.data();
  for (size_t i = 0; i < n; ++i) blocked[i] = (v[i] == kUnknown) | (v[i] >= kBlockedThreshold);
  int64_t blocked_count = 0;
  for (size_t i = 0; i < n; ++i) blocked_count += blocked[i];
  grid.blocked_count_ = blocked_count;
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
