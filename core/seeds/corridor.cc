#include "core/seeds/corridor.h"

#include <algorithm>
#include <cmath>

namespace swarmplan {
namespace {

Point2 UnitOr(const Point2& v, const Point2& fallback) {
  const double n = v.norm();
  return n > 0 ? Point2(v / n) : fallback;
}

Point2 LeftNormal(const Point2& d) { return Point2(-d.y(), d.x()); }

}  // namespace

double FreeExtent(const CollisionChecker& checker, const Point2& p, const Point2& direction,
                  double clearance, double cap, double tolerance) {
  const Point3 from = Lift(p);
  if (!checker.PointFree(from, clearance)) return 0.0;
  if (checker.SegmentFree(from, Lift(p + cap * direction), clearance)) return cap;
  double free = 0.0, blocked = cap;
  while (blocked - free > tolerance) {
    const double mid = 0.5 * (free + blocked);
    if (checker.SegmentFree(from, Lift(p + mid * direction), clearance)) {
      free = mid;
    } else {
      blocked = mid;
    }
  }
  return free;
}

CorridorSection SectionAt(const CollisionChecker& checker, const Point2& point,
                          const Point2& normal, double clearance, double cap, double tolerance) {
  CorridorSection section;
  section.point = point;
  section.normal = normal;
  section.left = FreeExtent(checker, point, normal, clearance, cap, tolerance);
  section.right = FreeExtent(checker, point, -normal, clearance, cap, tolerance);
  return section;
}

Point2 SegmentNormal(const Path& path, size_t i) {
  return LeftNormal(UnitOr((path[i + 1] - path[i]).head<2>(), Point2(1.0, 0.0)));
}

Point2 VertexNormal(const Path& path, size_t i) {
  const Point2 in = UnitOr((path[i] - path[i - 1]).head<2>(), Point2(1.0, 0.0));
  const Point2 out = UnitOr((path[i + 1] - path[i]).head<2>(), in);
  return LeftNormal(UnitOr(in + out, in));
}

PathPosition PositionAt(const Path& path, double s) {
  PathPosition position;
  if (path.empty()) return position;
  position.point = path.front().head<2>();
  double walked = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Point2 a = path[i].head<2>(), b = path[i + 1].head<2>();
    const double segment = (b - a).norm();
    position.segment = i;
    if (walked + segment >= s || i + 2 == path.size()) {
      const double t = segment > 0 ? std::clamp((s - walked) / segment, 0.0, 1.0) : 0.0;
      position.point = a + t * (b - a);
      return position;
    }
    walked += segment;
  }
  return position;
}

}  // namespace swarmplan
