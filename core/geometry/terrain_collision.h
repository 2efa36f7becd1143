#pragma once

#include "core/geometry/collision.h"
#include "core/map/terrain.h"

namespace swarmplan {

// Collision checking on a Terrain, in world coordinates (see Terrain). Clearance is the height
// above the bilinear ground, z - GroundAt(x, y). The map is the cell-centre rectangle
// min_xy() .. max_xy() up to the ceiling: outside it, and wherever the ground has no data,
// clearance is -infinity. The ceiling bounds the map; it is not an obstacle.
class TerrainCollisionChecker final : public CollisionChecker {
 public:
  explicit TerrainCollisionChecker(const Terrain& terrain) : terrain_(terrain) {}

  double Clearance(const Point3& p) const override;
  // Exact: the smallest height above the ground along the segment. The segment is split where
  // it crosses the lines between cell centres; over each piece the bilinear ground is a
  // quadratic in the segment's parameter, minimised in closed form.
  double SegmentClearance(const Point3& a, const Point3& b) const override;

 private:
  const Terrain& terrain_;
};

}  // namespace swarmplan
