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
  // Checked, then counted, in loops without an exit per cell, which the compiler vectorises:
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
  int64_t blocked_count = 0;
  for (size_t i = 0; i < n; ++i) blocked_count += IsBlockedValue(v[i]);
  grid.blocked_count_ = blocked_count;
  grid.cells_ = std::move(cells);
  return grid;
}

OccupancyGrid OccupancyGrid::WithBlocked(const std::vector<Cell>& cells) const {
  OccupancyGrid grid = *this;  // sharing this grid's distance field
  // The newly blocked cells matter only to a field derived from this grid's computed one.
  const bool derive = distance_field_computed();
  std::vector<Cell> added;
  for (const Cell& c : cells) {
    if (!InBounds(c) || IsBlockedValue(grid.cells_[Index(c.x, c.y)])) continue;
    grid.cells_[Index(c.x, c.y)] = kOccupied;
    ++grid.blocked_count_;
    if (derive) added.push_back(c);
  }
  if (grid.blocked_count_ == blocked_count_) return grid;  // the same cells: the same field
  grid.distance_ = std::make_shared<LazyDistanceField>();
  if (derive) {
    grid.distance_->base = distance_;
    grid.distance_->added = std::move(added);
  }
  return grid;
}

const std::vector<double>& OccupancyGrid::ComputeDistanceField() const {
  LazyDistanceField& field = *distance_;
  std::call_once(field.once, [&] {
    if (field.base != nullptr) {
      field.values = DerivedDistanceField(field.base->values, field.added);
      field.base.reset();
      field.added = {};
    } else {
      std::vector<uint8_t> blocked(cells_.size());
      for (size_t i = 0; i < cells_.size(); ++i) blocked[i] = IsBlockedValue(cells_[i]);
      field.values = SquaredDistanceTransform(width_, height_, blocked);
      for (double& d : field.values) d = std::sqrt(d) * resolution_;
    }
    field.ready.store(true, std::memory_order_release);
  });
  return field.values;
}

std::vector<double> OccupancyGrid::DerivedDistanceField(const std::vector<double>& base,
                                                        const std::vector<Cell>& added) const {
  // The nearest blocked cell is the base's or one of `added`: the field is the smaller of the
  // base's and the distance to `added`, in squared whole cells before the square root exactly as
  // a transform of the whole grid would give it. Only cells within the base's largest distance
  // of an added cell can come nearer to it, so the distance to `added` is measured in their
  // bounding box widened by that distance.
  std::vector<double> values = base;
  const double largest = *std::max_element(base.begin(), base.end());
  const int reach = std::isfinite(largest) && largest / resolution_ < width_ + height_
                        ? static_cast<int>(std::ceil(largest / resolution_)) + 1
                        : width_ + height_;
  int x0 = width_, y0 = height_, x1 = -1, y1 = -1;
  for (const Cell& c : added) {
    x0 = std::min(x0, c.x);
    y0 = std::min(y0, c.y);
    x1 = std::max(x1, c.x);
    y1 = std::max(y1, c.y);
  }
  x0 = std::max(0, x0 - reach);
  y0 = std::max(0, y0 - reach);
  x1 = std::min(width_ - 1, x1 + reach);
  y1 = std::min(height_ - 1, y1 + reach);
  const int box_width = x1 - x0 + 1, box_height = y1 - y0 + 1;
  std::vector<uint8_t> in_box(static_cast<size_t>(box_width) * box_height, 0);
  for (const Cell& c : added) in_box[static_cast<size_t>(c.y - y0) * box_width + (c.x - x0)] = 1;
  const std::vector<double> squared = SquaredDistanceTransform(box_width, box_height, in_box);
  for (int y = y0; y <= y1; ++y) {
    const double* from = squared.data() + static_cast<size_t>(y - y0) * box_width;
    double* to = values.data() + Index(x0, y);
    for (int i = 0; i < box_width; ++i) to[i] = std::min(to[i], std::sqrt(from[i]) * resolution_);
  }
  return values;
}

Cell OccupancyGrid::CellAt(const Point2& p) const {
  const Point2 local = (p - origin_) / resolution_;
  return Cell{static_cast<int>(std::floor(local.x())), static_cast<int>(std::floor(local.y()))};
}

}  // namespace swarmplan
