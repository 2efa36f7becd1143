#pragma once

// The canyon of the BAS reproduction: a generated, seeded height field standing in for the
// paper's (unpublished) 3D canyon map.

#include <cstdint>
#include <string>
#include <vector>

#include "core/map/point.h"

namespace swarmplan::bench {

// The canyon's shape. Columns x = 0..width-1 run from start to goal; rows y = 0..depth-1.
// Two branches split at the start's column and join again at the goal's, around a central mesa:
//   c_right(x) = mouth_y + right_bulge sin(pi u) + right_wiggle sin(3 pi u),  u = x / (width-1)
//   c_left(x)  = mouth_y - left_bulge sin(pi u)
//   h(x, y) = plateau - max((plateau - right_floor) g(y - c_right(x)),
//                           (plateau - left_floor) g(y - c_left(x))) + rocks(x, y)
//   g(d) = exp(-(d / half_width)^2)
//   rocks(x, y) = sum_k a_k exp(-((x - x_k)^2 + (y - y_k)^2) / r_k^2), k < rocks, with x_k, y_k
//   uniform over the map, a_k uniform in [rock_min, rock_max], r_k uniform in [1, 2.5]
//   (swarmplan::Rng seeded with `seed`, drawn in that order).
// The winding right branch is deep (the global optimum of the paper's fitness, which adds the
// height of every waypoint); the straighter left branch is shallower (a local optimum).
struct CanyonShape {
  int width = 21;  // the paper's 21 columns (i = 1..21)
  int depth = 21;
  double mouth_y = 10.0;
  double plateau = 13.0;
  double right_floor = 3.0;
  double left_floor = 9.0;
  double half_width = 4.0;
  double right_bulge = 4.0;
  double right_wiggle = 1.0;
  double left_bulge = 4.0;
  int rocks = 14;
  double rock_min = 0.3;
  double rock_max = 1.5;
};

// Heights row-major (index y * width + x), rounded to 0.01 so that the .asc text is exact.
std::vector<double> CanyonHeights(const CanyonShape& shape, uint64_t seed);

// Centre lines of the two branches at column x.
double RightBranchY(const CanyonShape& shape, double x);
double LeftBranchY(const CanyonShape& shape, double x);

// ESRI ASCII grid text of row-major heights (first data row the northernmost, y = depth - 1),
// cell size 1, the centre of cell (0, 0) at the origin (so world coordinates are cell indices).
std::string HeightsToAsc(int width, int depth, const std::vector<double>& heights);

}  // namespace swarmplan::bench
