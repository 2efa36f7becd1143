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
// the ceiling are in the same vertical unit. Paths on a terrain are in world coordinates: x and y
// in the horizontal unit of cell_size and origin (the lower-left corner of cell 0, 0, so the
// centre of cell i, j is origin + (i + 1/2, j + 1/2) * cell_size), z a height. Nothing converts
// between the two units: a file whose cell size is in degrees gives horizontal coordinates in
// degrees. The ground is the bilinear interpolation of the heights between cell centres, so the
// map spans the cell centres: CellCentre(0, 0) .. CellCentre(width-1, depth-1). Cells without
// data (NaN) are impassable at any height. Immutable; shared between jobs.
class Terrain {
 public:
  // `heights` is row-major, width * depth values, NaN for no data. `origin` is the world position
  // of the lower-left corner of cell (0, 0). When `ceiling` is NaN it is set to the highest
  // ground plus the relief (max - min), at least 1.
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

  // World <-> cell coordinates: cell coordinates are fractional cell indices with the cell
  // centres at integers.
  Point2 ToCell(const Point2& world) const { return (world - first_centre_) / cell_size_; }
  Point2 ToWorld(const Point2& cell) const { return first_centre_ + cell * cell_size_; }
  Point2 CellCentre(int x, int y) const { return ToWorld(Point2(x, y)); }
  // The map's horizontal extent in world coordinates: the first and the last cell centre.
  const Point2& min_xy() const { return first_centre_; }
  Point2 max_xy() const { return CellCentre(width_ - 1, depth_ - 1); }

  // Bilinear ground height at a world point; NaN outside the map or where any corner of the
  // cell-centre square around the point has no data.
  double GroundAt(const Point2& world) const {
    const Point2 cell = ToCell(world);
    return GroundAtCell(cell.x(), cell.y());
  }
  // The same at a point in cell coordinates (x in [0, width-1], y in [0, depth-1]).
  double GroundAtCell(double x, double y) const;

 private:
  Terrain() = default;
  int width_ = 0;
  int depth_ = 0;
  double cell_size_ = 1.0;
  Point2 origin_ = Point2::Zero();
  Point2 first_centre_ = Point2::Zero();  // origin_ + cell_size_ / 2
  double ceiling_ = 0.0;
  double min_height_ = 0.0;
  double max_height_ = 0.0;
  std::vector<double> heights_;
};

}  // namespace swarmplan
