#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <vector>

namespace swarmplan {

using Point2 = Eigen::Vector2d;
using Point3 = Eigen::Vector3d;

// A path in world coordinates. On 2D maps z is 0.
using Path = std::vector<Point3>;

// Integer cell of a grid: x is the column, y the row.
struct Cell {
  int x = 0;
  int y = 0;
  friend bool operator==(const Cell&, const Cell&) = default;
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// A 2D point at height 0.
inline Point3 Lift(const Point2& p) { return Point3(p.x(), p.y(), 0.0); }

// floor(v) as an int without a libm call (v within the int range): cell indices in hot loops.
inline int FloorToInt(double v) {
  const int i = static_cast<int>(v);
  return v < i ? i - 1 : i;
}

// One integer per cell, for hash sets and maps of cells.
inline int64_t CellKey(Cell c) {
  return (static_cast<int64_t>(c.y) << 32) ^ static_cast<uint32_t>(c.x);
}

}  // namespace swarmplan
