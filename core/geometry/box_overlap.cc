#include "core/geometry/box_overlap.h"

#include <algorithm>

#include "core/geometry/primitives.h"

namespace swarmplan {

bool SegmentEntersOpenBox(const Point2& a, const Point2& b, const Bounds2& box) {
  double t0 = 0.0, t1 = 1.0;
  const Point2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = box.min[axis], hi = box.max[axis];
    if (d[axis] == 0.0) {
      if (a[axis] <= lo || a[axis] >= hi) return false;
      continue;
    }
    double ta = (lo - a[axis]) / d[axis];
    double tb = (hi - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 >= t1) return false;
  }
  const Point2 mid = a + 0.5 * (t0 + t1) * d;
  return mid.x() > box.min.x() && mid.x() < box.max.x() && mid.y() > box.min.y() &&
         mid.y() < box.max.y();
}

bool PolygonOverlapsOpenBox(const std::vector<Point2>& polygon, const Bounds2& box) {
  if (LocatePoint(0.5 * (box.min + box.max), polygon) == PointLocation::kInside) return true;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    if (SegmentEntersOpenBox(polygon[j], polygon[i], box)) return true;
  }
  return false;
}

bool CircleOverlapsOpenBox(const Circle& circle, const Bounds2& box) {
  return BoxDistance(Bounds2{circle.center, circle.center}, box) < circle.radius;
}

}  // namespace swarmplan
