#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/map/point.h"

namespace swarmplan {

// A signed distance to the obstacles, sampled at the centres of a regular grid of square cells
// (world units, stored as float): positive in free space, negative inside obstacles. Built from
// a conservative raster, in which every cell that meets an obstacle is blocked; a free cell
// holds (distance from its centre to the nearest blocked centre) - h / 2, a blocked cell minus
// (distance to the nearest free centre) - h / 2, h the cell size. The value at the centre of
// the cell holding a point p is at most the true distance of p plus kCellSlack * h: the
// engines skip exact tests by it. Values are capped by the distance to the field's edge when
// the edge is not known to be clear (obstacles beyond it are not rasterised).
class DistanceField {
 public:
  // Lower bound slack: true distance of p >= CellValue(cell of p) - kCellSlack * cell_size()
  // (0.21 h from the raster, 0.71 h from p to its cell's centre, the rest for rounding).
  static constexpr double kCellSlack = 1.0;

  DistanceField() = default;
  // `blocked` is row-major width * height (> 0 each); cell (x, y) covers origin + [x, x + 1) *
  // cell, [y, y + 1) * cell. `cap_at_edge`: cap every value by its centre's distance to the
  // field's edge; otherwise a field without blocked cells holds its diagonal.
  static DistanceField FromBlockedCells(int width, int height, const std::vector<uint8_t>& blocked,
                                        double cell, const Point2& origin, bool cap_at_edge);

  bool empty() const { return values_.empty(); }
  int width() const { return width_; }
  int height() const { return height_; }
  double cell_size() const { return cell_; }
  double inverse_cell_size() const { return inv_cell_; }
  const Point2& origin() const { return origin_; }
  size_t MemoryBytes() const { return values_.size() * sizeof(float); }
  // The most Bilinear changes per world unit moved (its Lipschitz constant): the largest
  // differences between neighbouring centres along x and along y over the cell size, combined.
  double slope_bound() const { return slope_bound_; }
  // How far Bilinear anywhere in a cell may lie below that cell's CellValue.
  double bilinear_drop_bound() const { return bilinear_drop_bound_; }

  // The value at the centre of cell (x, y), which must be inside the field.
  float CellValue(int x, int y) const { return values_[static_cast<size_t>(y) * width_ + x]; }
  const float* values() const { return values_.data(); }
  // Bilinear interpolation between the cell centres, clamped to the field: continuous in p.
  double Bilinear(double x, double y) const {
    return BilinearAtGrid((x - origin_.x()) * inv_cell_, (y - origin_.y()) * inv_cell_);
  }
  // The same at grid coordinates (u, v) = (p - origin) / cell size.
  double BilinearAtGrid(double u, double v) const {
    const double gx = std::clamp(u - 0.5, 0.0, width_ - 1.0);
    const double gy = std::clamp(v - 0.5, 0.0, height_ - 1.0);
    const int ix = std::min(static_cast<int>(gx), last_x_);
    const int iy = std::min(static_cast<int>(gy), last_y_);
    const double tx = gx - ix, ty = gy - iy;
    const float* p = values_.data() + static_cast<size_t>(iy) * width_ + ix;
    const double bottom = p[0] + tx * (p[step_x_] - p[0]);
    const double top = p[step_y_] + tx * (p[step_y_ + step_x_] - p[step_y_]);
    return bottom + ty * (top - bottom);
  }
  // Whether Bilinear is at least `floor` at every point a + (b - a) k / n, k = 0..n, with n the
  // fewest pieces no longer than half a cell. Stretches whose end samples clear the floor by
  // more than slope_bound() lets the value fall between them are accepted unread, so open
  // space costs a few reads per segment; the verdict is the dense check's.
  bool SegmentKeeps(const Point2& a, const Point2& b, double floor) const;
  // The integral of max(0, floor - Bilinear) along [a, b], by the trapezoid rule at the points
  // SegmentKeeps reads; 0 where SegmentKeeps holds, without reading them all.
  double ShortfallAlong(const Point2& a, const Point2& b, double floor) const;

 private:
  int width_ = 0, height_ = 0;
  // The last cell a bilinear patch starts at, and the steps to the next column and row (0 on
  // a field one cell wide or high).
  int last_x_ = 0, last_y_ = 0, step_x_ = 0, step_y_ = 0;
  double cell_ = 1.0, inv_cell_ = 1.0;
  double slope_bound_ = 0.0;
  double bilinear_drop_bound_ = 0.0;
  Point2 origin_ = Point2::Zero();
  std::vector<float> values_;
};

}  // namespace swarmplan
