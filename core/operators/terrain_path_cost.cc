#include "core/operators/terrain_path_cost.h"

#include <cmath>

namespace swarmplan {

double TerrainSegmentCost(const Point3& a, const Point3& b, double cell_size) {
  return (b - a).norm() + b.z() * (std::abs(b.x() - a.x()) / cell_size);
}

double TerrainPathCost(const Path& path, double cell_size) {
  double cost = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    cost += TerrainSegmentCost(path[i], path[i + 1], cell_size);
  }
  return cost;
}

}  // namespace swarmplan
