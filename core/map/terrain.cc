#include "core/map/terrain.h"

#include <algorithm>
#include <cmath>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "core/map/world_range.h"

namespace swarmplan {

absl::StatusOr<Terrain> Terrain::Create(int width, int depth, std::vector<double> heights,
                                        double cell_size, Point2 origin, double ceiling,
                                        const MapLimits& limits) {
  if (width < 2 || depth < 2) {
    return absl::InvalidArgumentError(
        absl::StrCat("terrain size ", width, " x ", depth, " must be at least 2 x 2"));
  }
  const int64_t count = static_cast<int64_t>(width) * depth;
  if (count > limits.max_cells) {
    return absl::ResourceExhaustedError(absl::StrCat("terrain of ", width, " x ", depth, " = ",
                                                     count, " cells exceeds the limit of ",
                                                     limits.max_cells, " cells"));
  }
  if (static_cast<int64_t>(heights.size()) != count) {
    return absl::InvalidArgumentError(absl::StrCat("terrain of ", width, " x ", depth, " needs ",
                                                   count, " heights, got ", heights.size()));
  }
  if (!std::isfinite(cell_size) || cell_size <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("cell size must be a positive number, got ", cell_size));
  }
  if (absl::Status s =
          CheckRasterInWorldRange(origin, cell_size, width, depth, "cell size", "terrain");
      !s.ok()) {
    return s;
  }
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (size_t i = 0; i < heights.size(); ++i) {
    const double h = heights[i];
    if (std::isnan(h)) continue;
    if (!InWorldRange(h)) {
      return absl::InvalidArgumentError(absl::StrCat("height at ", i % width, ",", i / width,
                                                     " is not finite or beyond +-",
                                                     kMaxWorldCoordinate));
    }
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  if (lo > hi) return absl::InvalidArgumentError("terrain has no cell with data");
  if (std::isnan(ceiling)) ceiling = hi + std::max(1.0, hi - lo);
  if (!InWorldRange(ceiling) || ceiling <= hi) {
    return absl::InvalidArgumentError(
        absl::StrCat("ceiling ", ceiling, " must be above the highest ground ", hi));
  }
  Terrain t;
  t.width_ = width;
  t.depth_ = depth;
  t.cell_size_ = cell_size;
  t.origin_ = origin;
  t.first_centre_ = origin + Point2::Constant(cell_size / 2);
  t.ceiling_ = ceiling;
  t.min_height_ = lo;
  t.max_height_ = hi;
  t.heights_ = std::move(heights);
  return t;
}

double Terrain::GroundAtCell(double x, double y) const {
  if (!(x >= 0 && y >= 0 && x <= width_ - 1 && y <= depth_ - 1)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const int x0 = std::min(static_cast<int>(x), width_ - 2);
  const int y0 = std::min(static_cast<int>(y), depth_ - 2);
  const double fx = x - x0;
  const double fy = y - y0;
  const double h00 = HeightAt(x0, y0), h10 = HeightAt(x0 + 1, y0);
  const double h01 = HeightAt(x0, y0 + 1), h11 = HeightAt(x0 + 1, y0 + 1);
  return (1 - fy) * ((1 - fx) * h00 + fx * h10) + fy * ((1 - fx) * h01 + fx * h11);
}

}  // namespace swarmplan
