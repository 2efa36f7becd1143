#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/limits.h"
#include "core/map/point.h"

namespace swarmplan {

// A height field over columns x = 0..width-1 and rows y = 0..depth-1 (y grows north), with a
// ceiling: flight is allowed between the ground (plus clearance) and the ceiling. Heights and
// the ceiling are in the same vertical unit; cell_size and origin place the grid in the world
// and are kept for export. Paths on a terrain are in grid coordinates: x and y are fractional
// cell indices (cell centres at integers), z is a height. Cells without data (NaN) are
// impassable at any height. Immutable; shared between jobs.
class Terrain {
 public:
  // `heights` is row-major, width * depth values, NaN for no data. When `ceiling` is NaN it is
  // set to the highest ground plus the relief (max - min), at least 1.
  static absl::StatusOr<Terrain> Create(int width, int depth, std::vector<double> heights,
                                        double cell_size = 1.0, Point2 origin = Point2::Zero(),
                                        double ceiling = std::numeric_limits<double>::quiet_NaN(),
                                        const MapLimits& limits = {});

  int width() const { return width_; }
  int depth() const { return depth_; }
  double cell_size() const { return cell_size_; }
  const Point2& origin() const { return origin_; }
  double ceiling() const { return ceiling_; }
  double min_height() const { return min_height_; }
  double max_height() const { return max_height_; }
  const std::vector<double>& heights() const { return heights_; }

  bool InBounds(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < depth_; }
  // NaN where there is no data.
  double HeightAt(int x, int y) const { return heights_[static_cast<size_t>(y) * width_ + x]; }
  // Bilinear ground height at a point in cell coordinates (x in [0, width-1], y in
  // [0, depth-1]); NaN outside or where any corner has no data.
  double GroundAt(double x, double y) const;

 private:
  Terrain() = default;
  int width_ = 0;
  int depth_ = 0;
  double cell_size_ = 1.0;
  Point2 origin_ = Point2::Zero();
  double ceiling_ = 0.0;
  double min_height_ = 0.0;
  double max_height_ = 0.0;
  std::vector<double> heights_;
};

}  // namespace swarmplan
