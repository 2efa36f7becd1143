#pragma once

#include <vector>

#include "core/map/point.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// Planar geometry shared by the collision checkers, the visibility graph and the planners.
// Polygons are simple and counter-clockwise as ShapeWorld stores them. Predicates that decide
// "on the boundary" use an absolute tolerance of kGeometryEpsilon (world units), which is far
// below any map feature and far above double rounding at map scales.

inline constexpr double kGeometryEpsilon = 1e-9;

inline double Cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

double PointSegmentDistance(const Point2& p, const Point2& a, const Point2& b);

enum class SegmentContact {
  kNone,      // no common point
  kTouching,  // common points, but only where an endpoint of one lies on the other (or overlap)
  kProper,    // the interiors cross at a single point, transversally
};
SegmentContact SegmentIntersection(const Point2& a, const Point2& b, const Point2& c,
                                   const Point2& d);
inline bool SegmentsIntersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  return SegmentIntersection(a, b, c, d) != SegmentContact::kNone;
}

// 0 when the segments meet.
double SegmentSegmentDistance(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

enum class PointLocation { kOutside, kBoundary, kInside };
PointLocation LocatePoint(const Point2& p, const std::vector<Point2>& polygon);
inline bool PointInPolygon(const Point2& p, const std::vector<Point2>& polygon) {
  return LocatePoint(p, polygon) != PointLocation::kOutside;
}

// Distance from p to the polygon's boundary, negated when p is inside (0 within
// kGeometryEpsilon of the boundary on the inside).
double SignedDistanceToPolygon(const Point2& p, const std::vector<Point2>& polygon);

// Smallest distance from the segment to the polygon when they do not meet. When they meet:
// <= 0, and negative exactly when part of the segment is inside (then the smallest signed
// distance at the endpoints and at the middles of the inside stretches: an upper bound of the
// deepest penetration, not the exact value).
double SegmentPolygonDistance(const Point2& a, const Point2& b, const std::vector<Point2>& polygon);

// Smallest distance from the segment to the closed disc; negative when the centre is closer
// than the radius (the value is then distance to centre minus radius).
double SegmentCircleDistance(const Point2& a, const Point2& b, const Circle& circle);

// True when some part of the segment lies in the polygon's open interior. Running along an
// edge, or touching a vertex or an edge from outside, is allowed.
bool SegmentCrossesPolygonInterior(const Point2& a, const Point2& b,
                                   const std::vector<Point2>& polygon);

// The same two questions for a convex counter-clockwise polygon, by half-planes: faster, with
// early exits. `Strictly inside` means more than kGeometryEpsilon inside every edge.
bool StrictlyInsideConvex(const Point2& p, const std::vector<Point2>& convex);
bool SegmentCrossesConvexInterior(const Point2& a, const Point2& b,
                                  const std::vector<Point2>& convex);

// The regular polygon circumscribed about the circle (so anything outside it is outside the
// circle), with the fewest sides (at least 6) such that its vertices are at most `tolerance`
// beyond the circle: sides = ceil(pi / acos(r / (r + tolerance))).
Polygon CircleToPolygon(const Circle& circle, double tolerance);

// Axis-aligned bounding box.
Bounds2 BoundingBox(const std::vector<Point2>& points);
// Smallest distance between two boxes (0 when they overlap).
double BoxDistance(const Bounds2& a, const Bounds2& b);
// Whether BoxDistance(a, b) exceeds d, without a square root: the pre-filter of exact distance
// and collision queries. Within rounding of d it answers false, so a caller that skips on true
// never skips a box that could matter.
bool BoxesFartherThan(const Bounds2& a, const Bounds2& b, double d);

bool IsConvex(const std::vector<Point2>& polygon);

// Pieces whose union contains every point within `radius` of the polygon (the Minkowski sum
// with a disc), and is contained in the Minkowski sum with a disc of radius + tolerance.
// Each piece is a convex counter-clockwise polygon: the polygon's edges pushed out by radius,
// joined at convex vertices by segments circumscribed about the arcs. A convex polygon gives
// one piece; a non-convex one is split into triangles by ear clipping and each triangle is
// grown (the Minkowski sum distributes over the union, so this is exact up to the arcs). The
// pieces of a non-convex polygon overlap by 2 * radius along the triangles' shared diagonals,
// so no segment can slip between them. Collinear vertices are dropped. With radius <= 0 the
// result is the polygon itself, unchanged (convex or not): triangles would share diagonals a
// segment could run along.
std::vector<Polygon> GrowPolygon(const Polygon& polygon, double radius, double tolerance);

// Triangles (counter-clockwise) covering a simple counter-clockwise polygon.
std::vector<Polygon> Triangulate(const Polygon& polygon);

}  // namespace swarmplan
