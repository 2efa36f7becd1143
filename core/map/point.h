#pragma once

#include <Eigen/Core>
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

}  // namespace swarmplan
