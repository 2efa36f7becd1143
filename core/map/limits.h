#pragma once

#include <cmath>
#include <cstdint>

namespace swarmplan {

// Bounds that keep a hostile or mistaken input from exhausting memory. Loaders and
// constructors reject anything larger with a clear error instead of allocating it.
struct MapLimits {
  int64_t max_cells = 64LL * 1024 * 1024;  // grid or terrain cells
  int64_t max_file_bytes = 256LL * 1024 * 1024;
  int64_t max_obstacles = 100000;  // circles + polygons in a ShapeWorld
  int64_t max_vertices = 1000000;  // polygon vertices in a ShapeWorld, in all
};

// Every map's coordinates and extents, in world units, lie within +-kMaxWorldCoordinate:
// distance fields keep distances as float and squared lengths must stay finite, so larger worlds
// are refused (1e12 m is far beyond any site a fleet plans on).
inline constexpr double kMaxWorldCoordinate = 1e12;
// False for NaN and infinities too.
inline bool InWorldRange(double v) { return std::abs(v) <= kMaxWorldCoordinate; }

}  // namespace swarmplan
