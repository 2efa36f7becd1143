#pragma once

#include <vector>

#include "core/geometry/collision.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// Exact collision checking on a ShapeWorld: distances to circles and polygons (negative inside
// a circle or polygon), -infinity outside the bounds. The bounds limit the map but are not an
// obstacle: clearance is measured to circles and polygons only. Obstacles are pre-filtered by
// their bounding boxes. The world must outlive the checker.
class ShapeCollisionChecker final : public CollisionChecker {
 public:
  explicit ShapeCollisionChecker(const ShapeWorld& world);

  double Clearance(const Point3& p) const override;
  // Exact smallest distance from the segment to the obstacles; <= 0 when it meets one.
  double SegmentClearance(const Point3& a, const Point3& b) const override;
  bool SegmentFree(const Point3& a, const Point3& b, double clearance) const override;

 private:
  const ShapeWorld& world_;
  std::vector<Bounds2> circle_boxes_;
  std::vector<Bounds2> polygon_boxes_;
};

}  // namespace swarmplan
