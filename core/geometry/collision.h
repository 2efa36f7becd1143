#pragma once

#include <memory>

#include "core/map/map.h"
#include "core/map/point.h"

namespace swarmplan {

// Validity and clearance queries on one map: const and thread-safe, shared by every planner.
// Clearance is the distance from a point to the nearest obstacle in world units (vertical
// height above the ground on terrain); it is negative or zero inside an obstacle and
// -infinity outside the map.
class CollisionChecker {
 public:
  virtual ~CollisionChecker() = default;

  virtual double Clearance(const Point3& p) const = 0;
  // Smallest clearance along the segment from a to b.
  virtual double SegmentClearance(const Point3& a, const Point3& b) const = 0;

  bool PointFree(const Point3& p, double clearance) const { return Clearance(p) >= clearance; }
  // True when every point of the segment is inside the map and keeps `clearance`. With
  // clearance 0 on a grid, true exactly when the segment touches no blocked cell (corners
  // included).
  virtual bool SegmentFree(const Point3& a, const Point3& b, double clearance) const {
    return SegmentClearance(a, b) >= clearance;
  }
  bool PathFree(const Path& path, double clearance) const;
  double PathClearance(const Path& path) const;
};

// The checker for the map's kind. The map must outlive the checker.
std::unique_ptr<const CollisionChecker> MakeCollisionChecker(const Map& map);

}  // namespace swarmplan
