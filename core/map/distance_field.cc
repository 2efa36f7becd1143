#include "core/map/distance_field.h"

#include <algorithm>
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
  return field;
}

double DistanceField::Bilinear(double x, double y) const {
  const double gx = std::clamp((x - origin_.x()) * inv_cell_ - 0.5, 0.0, width_ - 1.0);
  const double gy = std::clamp((y - origin_.y()) * inv_cell_ - 0.5, 0.0, height_ - 1.0);
  const int ix = std::min(static_cast<int>(gx), std::max(0, width_ - 2));
  const int iy = std::min(static_cast<int>(gy), std::max(0, height_ - 2));
  const double tx = gx - ix, ty = gy - iy;
  const int dx = width_ > 1 ? 1 : 0;
  const size_t row = static_cast<size_t>(width_) * (height_ > 1 ? 1 : 0);
  const float* v = values_.data() + static_cast<size_t>(iy) * width_ + ix;
  const double bottom = v[0] + tx * (v[dx] - v[0]);
  const double top = v[row] + tx * (v[row + dx] - v[row]);
  return bottom + ty * (top - bottom);
}

}  // namespace swarmplan
