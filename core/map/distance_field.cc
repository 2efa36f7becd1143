#include "core/map/distance_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/geometry/distance_transform.h"

namespace swarmplan {

DistanceField DistanceField::FromBlockedCells(int width, int height,
                                              const std::vector<uint8_t>& blocked, double cell,
                                              const Point2& origin, bool cap_at_edge) {
  DistanceField field;
  field.width_ = width;
  field.height_ = height;
  field.cell_ = cell;
  field.inv_cell_ = 1.0 / cell;
  field.origin_ = origin;
  field.last_x_ = std::max(0, width - 2);
  field.last_y_ = std::max(0, height - 2);
  field.step_x_ = width > 1 ? 1 : 0;
  field.step_y_ = height > 1 ? width : 0;
  std::vector<uint8_t> free(blocked.size());
  for (size_t i = 0; i < blocked.size(); ++i) free[i] = blocked[i] ? 0 : 1;
  const std::vector<double> to_blocked = SquaredDistanceTransform(width, height, blocked);
  const std::vector<double> to_free = SquaredDistanceTransform(width, height, free);
  const double diagonal = std::hypot(width, height) * cell;
  field.values_.resize(blocked.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      double value = blocked[i] ? -(std::sqrt(to_free[i]) * cell - 0.5 * cell)
                                : std::sqrt(to_blocked[i]) * cell - 0.5 * cell;
      if (!std::isfinite(value)) value = blocked[i] ? -diagonal : diagonal;
      if (cap_at_edge) {
        const double edge = cell * (0.5 + std::min({x, y, width - 1 - x, height - 1 - y}));
        value = std::min(value, edge);
      }
      field.values_[i] = static_cast<float>(value);
    }
  }
  double step_x = 0.0, step_y = 0.0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double v = field.CellValue(x, y);
      if (x + 1 < width) step_x = std::max(step_x, std::abs(field.CellValue(x + 1, y) - v));
      if (y + 1 < height) step_y = std::max(step_y, std::abs(field.CellValue(x, y + 1) - v));
    }
  }
  field.slope_bound_ = std::hypot(step_x, step_y) / cell;
  // Bilinear equals CellValue at a centre and moves at most step_x (step_y) per cell along x
  // (y); a point of a cell lies within half a cell of its centre along each. With room for the
  // rounding of the interpolation.
  field.bilinear_drop_bound_ = 0.5 * (step_x + step_y) * (1.0 + 1e-6) + 1e-6 * cell;
  return field;
}

namespace {

// The fewest pieces no longer than half a cell that a segment of `length` splits into.
int HalfCellPieces(double length, double cell) {
  return static_cast<int>(std::clamp(std::ceil(2.0 * length / cell), 1.0, double{1 << 30}));
}

}  // namespace

double DistanceField::ShortfallAlong(const Point2& a, const Point2& b, double floor) const {
  if (SegmentKeeps(a, b, floor)) return 0.0;
  const Point2 step = b - a;
  const int pieces = HalfCellPieces(step.norm(), cell_);
  double sum = 0.0;
  for (int k = 0; k <= pieces; ++k) {
    const Point2 p = a + step * (static_cast<double>(k) / pieces);
    const double weight = k == 0 || k == pieces ? 0.5 : 1.0;
    sum += weight * std::max(0.0, floor - Bilinear(p.x(), p.y()));
  }
  return sum * step.norm() / pieces;
}

bool DistanceField::SegmentKeeps(const Point2& a, const Point2& b, double floor) const {
  const Point2 step = b - a;
  const double length = step.norm();
  const int pieces = HalfCellPieces(length, cell_);
  auto sample = [&](int k) {
    const Point2 p = a + step * (static_cast<double>(k) / pieces);
    return Bilinear(p.x(), p.y());
  };
  const double first = sample(0), last = sample(pieces);
  if (first < floor || last < floor) return false;
  // Covers the rounding of the sample points and of the interpolation.
  const double slack =
      1e-9 * (1.0 + std::abs(floor) + slope_bound_ * (a.cwiseAbs().sum() + b.cwiseAbs().sum()));
  const double piece = length / pieces;
  // Stretches of samples [lo, hi] whose end values are known to be at least the floor, searched
  // depth first: at most two per level of halving are pending.
  struct Stretch {
    int lo, hi;
    double lo_value, hi_value;
  };
  std::array<Stretch, 72> pending;
  size_t count = 0;
  pending[count++] = Stretch{0, pieces, first, last};
  while (count > 0) {
    const Stretch s = pending[--count];
    if (s.hi - s.lo < 2) continue;
    const double fall = slope_bound_ * 0.5 * (s.hi - s.lo) * piece;
    if (std::min(s.lo_value, s.hi_value) - fall - slack >= floor) continue;
    const int mid = s.lo + (s.hi - s.lo) / 2;
    const double value = sample(mid);
    if (value < floor) return false;
    pending[count++] = Stretch{mid, s.hi, value, s.hi_value};
    pending[count++] = Stretch{s.lo, mid, s.lo_value, value};
  }
  return true;
}

}  // namespace swarmplan
