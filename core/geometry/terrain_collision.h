#pragma once

#include "core/geometry/collision.h"
#include "core/map/terrain.h"

namespace swarmplan {

// Collision checking on a Terrain, in grid coordinates (x, y fractional cell indices, z a
// height). Clearance is the height above the bilinear ground, z - GroundAt(x, y). The map is
// 0 <= x <= width - 1, 0 <= y <= depth - 1, z <= ceiling: outside it, and wherever the ground
// has no data, clearance is -infinity. The ceiling bounds the map; it is not an obstacle.
class TerrainCollisionChecker final : public CollisionChecker {
 public:
  // Segments are sampled at most this far apart (in cells, horizontally), endpoints included.
  static constexpr double kSampleStep = 0.25;

  explicit TerrainCollisionChecker(const Terrain& terrain) : terrain_(terrain) {}

  double Clearance(const Point3& p) const override;
  // Smallest clearance over the samples.
  double SegmentClearance(const Point3& a, const Point3& b) const override;
  bool SegmentFree(const Point3& a, const Point3& b, double clearance) const override;

 private:
  template <typename Visit>
  void ForEachSample(const Point3& a, const Point3& b, Visit&& visit) const;

  const Terrain& terrain_;
};

}  // namespace swarmplan
