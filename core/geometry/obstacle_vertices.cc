#include "core/geometry/obstacle_vertices.h"

#include <algorithm>

#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

bool BoxesOverlap(const Bounds2& a, const Bounds2& b) {
  return a.min.x() <= b.max.x() + kGeometryEpsilon && b.min.x() <= a.max.x() + kGeometryEpsilon &&
         a.min.y() <= b.max.y() + kGeometryEpsilon && b.min.y() <= a.max.y() + kGeometryEpsilon;
}

}  // namespace

bool GrownObstacles::Contains(const Point2& p) const {
  const Bounds2 box{p, p};
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (!BoxesOverlap(box, boxes[i])) continue;
    if (convex[i] ? StrictlyInsideConvex(p, pieces[i].vertices)
                  : LocatePoint(p, pieces[i].vertices) == PointLocation::kInside) {
      return true;
    }
  }
  return false;
}

bool GrownObstacles::Blocks(const Point2& a, const Point2& b) const {
  const Bounds2 box{a.cwiseMin(b), a.cwiseMax(b)};
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (!BoxesOverlap(box, boxes[i])) continue;
    if (convex[i] ? SegmentCrossesConvexInterior(a, b, pieces[i].vertices)
                  : SegmentCrossesPolygonInterior(a, b, pieces[i].vertices)) {
      return true;
    }
  }
  return false;
}

bool GrownObstacles::Tangent(const Point2& from, const Corner& corner) const {
  const std::vector<Point2>& v = pieces[corner.piece].vertices;
  const size_t n = v.size();
  const Point2& prev = v[(corner.index + n - 1) % n];
  const Point2& next = v[(corner.index + 1) % n];
  const Point2 dir = corner.point - from;
  const double len = dir.norm();
  if (len == 0.0) return true;
  const double side_prev = Cross(dir, prev - corner.point) / len;
  const double side_next = Cross(dir, next - corner.point) / len;
  return !((side_prev > kGeometryEpsilon && side_next < -kGeometryEpsilon) ||
           (side_prev < -kGeometryEpsilon && side_next > kGeometryEpsilon));
}

GrownObstacles GrowObstacles(const ShapeWorld& world, double radius, double circle_tolerance) {
  GrownObstacles out;
  const double margin = GrownObstacles::kGrowMargin;
  for (const Circle& c : world.circles()) {
    out.pieces.push_back(
        CircleToPolygon(Circle{c.center, c.radius + radius + margin}, circle_tolerance));
  }
  for (const Polygon& p : world.polygons()) {
    for (Polygon& piece : GrowPolygon(p, radius > 0 ? radius + margin : 0.0, circle_tolerance)) {
      out.pieces.push_back(std::move(piece));
    }
  }
  out.boxes.reserve(out.pieces.size());
  out.convex.reserve(out.pieces.size());
  for (const Polygon& p : out.pieces) {
    out.boxes.push_back(BoundingBox(p.vertices));
    out.convex.push_back(IsConvex(p.vertices) ? 1 : 0);
  }
  for (size_t i = 0; i < out.pieces.size(); ++i) {
    const std::vector<Point2>& v = out.pieces[i].vertices;
    const size_t n = v.size();
    for (size_t k = 0; k < n; ++k) {
      const Point2& prev = v[(k + n - 1) % n];
      const Point2& next = v[(k + 1) % n];
      if (Cross(v[k] - prev, next - v[k]) <= 0) continue;  // reflex or flat
      if (!world.bounds().Contains(v[k]) || out.Contains(v[k])) continue;
      out.corners.push_back({v[k], static_cast<int>(i), static_cast<int>(k)});
    }
  }
  std::sort(out.corners.begin(), out.corners.end(),
            [](const GrownObstacles::Corner& a, const GrownObstacles::Corner& b) {
              if (a.point.x() != b.point.x()) return a.point.x() < b.point.x();
              if (a.point.y() != b.point.y()) return a.point.y() < b.point.y();
              return a.piece != b.piece ? a.piece < b.piece : a.index < b.index;
            });
  return out;
}

std::vector<Point2> ObstacleVertices(const ShapeWorld& world, double radius,
                                     double circle_tolerance) {
  const GrownObstacles grown = GrowObstacles(world, radius, circle_tolerance);
  std::vector<Point2> points;
  points.reserve(grown.corners.size());
  for (const GrownObstacles::Corner& c : grown.corners) points.push_back(c.point);
  return points;
}

}  // namespace swarmplan
