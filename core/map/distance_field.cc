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
  return field;
}

}  // namespace swarmplan
