#include "core/geometry/collision.h"

#include <algorithm>
#include <limits>

#include "core/geometry/grid_collision.h"
#include "core/geometry/shape_collision.h"
#include "core/geometry/terrain_collision.h"

namespace swarmplan {

bool CollisionChecker::PathFree(const Path& path, double clearance) const {
  if (path.empty()) return false;
  if (path.size() == 1) return PointFree(path.front(), clearance);
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    if (!SegmentFree(path[i], path[i + 1], clearance)) return false;
  }
  return true;
}

double CollisionChecker::PathClearance(const Path& path) const {
  if (path.empty()) return -std::numeric_limits<double>::infinity();
  // A segment's clearance is exact where a point's may be a bound (far from obstacles on grids).
  if (path.size() == 1) return SegmentClearance(path.front(), path.front());
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    best = std::min(best, SegmentClearance(path[i], path[i + 1]));
  }
  return best;
}

std::unique_ptr<const CollisionChecker> MakeCollisionChecker(const Map& map) {
  switch (map.kind()) {
    case MapKind::kOccupancyGrid:
      return std::make_unique<GridCollisionChecker>(*map.grid());
    case MapKind::kShapeWorld:
      return std::make_unique<ShapeCollisionChecker>(*map.world());
    case MapKind::kTerrain:
      return std::make_unique<TerrainCollisionChecker>(*map.terrain());
  }
  return nullptr;
}

}  // namespace swarmplan
