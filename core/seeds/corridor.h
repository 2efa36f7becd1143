#pragma once

#include <vector>

#include "core/geometry/collision.h"
#include "core/map/point.h"

namespace swarmplan {

// How far a point can move from `p` along the unit vector `direction` while the segment it
// sweeps stays in the map and keeps `clearance` from every obstacle, up to `cap` (world units),
// by bisection on the map's own CollisionChecker to within `tolerance`. 0 when p itself does
// not keep the clearance.
double FreeExtent(const CollisionChecker& checker, const Point2& p, const Point2& direction,
                  double clearance, double cap, double tolerance);

// The free space across a path at one point: the unit normal there and how far the point can
// move along +normal (`left`) and -normal (`right`) keeping the clearance.
struct CorridorSection {
  Point2 point = Point2::Zero();
  Point2 normal = Point2::Zero();
  double left = 0.0;
  double right = 0.0;
};

// The section at `point` across `normal` (unit), its extents capped at `cap`.
CorridorSection SectionAt(const CollisionChecker& checker, const Point2& point,
                          const Point2& normal, double clearance, double cap, double tolerance);

// The unit normal, left of the direction of travel, of segment i -> i + 1 of `path`, and at
// interior vertex i (the bisector of the turn).
Point2 SegmentNormal(const Path& path, size_t i);
Point2 VertexNormal(const Path& path, size_t i);

// The point at arc length `s` along `path` (clamped to the path; horizontal length), and the
// index of its segment.
struct PathPosition {
  Point2 point = Point2::Zero();
  size_t segment = 0;
};
PathPosition PositionAt(const Path& path, double s);

}  // namespace swarmplan
