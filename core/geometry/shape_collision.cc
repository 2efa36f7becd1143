#include "core/geometry/shape_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

Bounds2 PointBox(const Point2& p) { return Bounds2{p, p}; }

Bounds2 SegmentBox(const Point2& a, const Point2& b) {
  return Bounds2{a.cwiseMin(b), a.cwiseMax(b)};
}

}  // namespace

ShapeCollisionChecker::ShapeCollisionChecker(const ShapeWorld& world) : world_(world) {
  circle_boxes_.reserve(world.circles().size());
  for (const Circle& c : world.circles()) {
    const Point2 r(c.radius, c.radius);
    circle_boxes_.push_back(Bounds2{c.center - r, c.center + r});
  }
  polygon_boxes_.reserve(world.polygons().size());
  for (const Polygon& p : world.polygons()) polygon_boxes_.push_back(BoundingBox(p.vertices));
}

double ShapeCollisionChecker::Clearance(const Point3& p3) const {
  const Point2 p = p3.head<2>();
  if (!world_.bounds().Contains(p)) return -kInf;
  const Bounds2 box = PointBox(p);
  double best = kInf;
  for (size_t i = 0; i < world_.circles().size(); ++i) {
    const Circle& c = world_.circles()[i];
    best = std::min(best, (p - c.center).norm() - c.radius);
  }
  for (size_t i = 0; i < world_.polygons().size(); ++i) {
    if (BoxesFartherThan(box, polygon_boxes_[i], best)) continue;
    best = std::min(best, SignedDistanceToPolygon(p, world_.polygons()[i].vertices));
  }
  return best;
}

double ShapeCollisionChecker::SegmentClearance(const Point3& a3, const Point3& b3) const {
  const Point2 a = a3.head<2>();
  const Point2 b = b3.head<2>();
  if (!world_.bounds().Contains(a) || !world_.bounds().Contains(b)) return -kInf;
  const Bounds2 box = SegmentBox(a, b);
  double best = kInf;
  for (size_t i = 0; i < world_.circles().size(); ++i) {
    if (BoxesFartherThan(box, circle_boxes_[i], best)) continue;
    best = std::min(best, SegmentCircleDistance(a, b, world_.circles()[i]));
  }
  for (size_t i = 0; i < world_.polygons().size(); ++i) {
    if (BoxesFartherThan(box, polygon_boxes_[i], best)) continue;
    best = std::min(best, SegmentPolygonDistance(a, b, world_.polygons()[i].vertices));
  }
  return best;
}

bool ShapeCollisionChecker::SegmentFree(const Point3& a3, const Point3& b3,
                                        double clearance) const {
  const Point2 a = a3.head<2>();
  const Point2 b = b3.head<2>();
  if (!world_.bounds().Contains(a) || !world_.bounds().Contains(b)) return false;
  const Bounds2 box = SegmentBox(a, b);
  for (size_t i = 0; i < world_.circles().size(); ++i) {
    if (BoxesFartherThan(box, circle_boxes_[i], clearance)) continue;
    if (SegmentCircleDistance(a, b, world_.circles()[i]) < clearance) return false;
  }
  for (size_t i = 0; i < world_.polygons().size(); ++i) {
    if (BoxesFartherThan(box, polygon_boxes_[i], clearance)) continue;
    if (SegmentPolygonDistance(a, b, world_.polygons()[i].vertices) < clearance) return false;
  }
  return true;
}

}  // namespace swarmplan
