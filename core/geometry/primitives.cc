#include "core/geometry/primitives.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swarmplan {
namespace {

constexpr double kEps = kGeometryEpsilon;

// Signed distance of p from the line through a and b (positive on the left); 0 when a == b.
double SideOf(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len = ab.norm();
  return len > 0 ? Cross(ab, p - a) / len : 0.0;
}

bool StrictlyOpposite(double u, double v) {
  return (u > kEps && v < -kEps) || (u < -kEps && v > kEps);
}

// Parameter of the projection of p onto the segment a + t (b - a), clamped to [0, 1].
double ProjectionParameter(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return 0.0;
  return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

// The polygon without repeated consecutive vertices.
std::vector<Point2> WithoutDuplicates(const std::vector<Point2>& v) {
  std::vector<Point2> out;
  out.reserve(v.size());
  for (const Point2& p : v) {
    if (out.empty() || (p - out.back()).norm() > kEps) out.push_back(p);
  }
  while (out.size() > 1 && (out.front() - out.back()).norm() <= kEps) out.pop_back();
  return out;
}

// The polygon without vertices where it goes straight on (or doubles back on itself); the
// polygon unchanged if fewer than three vertices would remain.
std::vector<Point2> WithoutCollinear(std::vector<Point2> v) {
  if (v.size() <= 3) return v;
  std::vector<Point2> out;
  out.reserve(v.size());
  for (const Point2& p : v) {
    while (out.size() >= 2 && std::abs(SideOf(out.back(), out[out.size() - 2], p)) <= kEps) {
      out.pop_back();
    }
    out.push_back(p);
  }
  bool changed = true;  // the vertices around the wrap-around point
  while (changed && out.size() > 3) {
    changed = false;
    if (std::abs(SideOf(out.back(), out[out.size() - 2], out.front())) <= kEps) {
      out.pop_back();
      changed = true;
    } else if (std::abs(SideOf(out.front(), out.back(), out[1])) <= kEps) {
      out.erase(out.begin());
      changed = true;
    }
  }
  return out.size() >= 3 ? out : v;
}

// Grows a convex counter-clockwise polygon (no duplicate vertices) by radius > 0.
Polygon GrowConvex(const std::vector<Point2>& v, double radius, double tolerance) {
  // Largest angle one circumscribed segment may span so it stays within tolerance of the arc.
  const double max_span = 2.0 * std::acos(radius / (radius + std::max(tolerance, 1e-12)));
  Polygon out;
  const size_t n = v.size();
  for (size_t i = 0; i < n; ++i) {
    const Point2& prev = v[(i + n - 1) % n];
    const Point2& cur = v[i];
    const Point2& next = v[(i + 1) % n];
    const Point2 e_in = (cur - prev).normalized();
    const Point2 e_out = (next - cur).normalized();
    const Point2 n_in(e_in.y(), -e_in.x());  // outward normal of a counter-clockwise polygon
    const double turn = std::atan2(Cross(e_in, e_out), e_in.dot(e_out));
    out.vertices.push_back(cur + radius * n_in);
    if (turn <= 0.0) continue;
    const int k = std::max(1, static_cast<int>(std::ceil(turn / std::max(max_span, 1e-6))));
    const double half = turn / (2.0 * k);
    const double reach = radius / std::cos(half);
    const double base = std::atan2(n_in.y(), n_in.x());
    for (int j = 0; j < k; ++j) {
      const double phi = base + half * (2 * j + 1);
      out.vertices.push_back(cur + reach * Point2(std::cos(phi), std::sin(phi)));
    }
    const Point2 n_out(e_out.y(), -e_out.x());
    out.vertices.push_back(cur + radius * n_out);
  }
  out.vertices = WithoutCollinear(WithoutDuplicates(out.vertices));
  return out;
}

bool InTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  return Cross(b - a, p - a) >= -kEps && Cross(c - b, p - b) >= -kEps &&
         Cross(a - c, p - c) >= -kEps;
}

}  // namespace

double PointSegmentDistance(const Point2& p, const Point2& a, const Point2& b) {
  return (p - (a + ProjectionParameter(p, a, b) * (b - a))).norm();
}

SegmentContact SegmentIntersection(const Point2& a, const Point2& b, const Point2& c,
                                   const Point2& d) {
  if (std::max(a.x(), b.x()) + kEps < std::min(c.x(), d.x()) ||
      std::max(c.x(), d.x()) + kEps < std::min(a.x(), b.x()) ||
      std::max(a.y(), b.y()) + kEps < std::min(c.y(), d.y()) ||
      std::max(c.y(), d.y()) + kEps < std::min(a.y(), b.y())) {
    return SegmentContact::kNone;
  }
  if (StrictlyOpposite(SideOf(c, a, b), SideOf(d, a, b)) &&
      StrictlyOpposite(SideOf(a, c, d), SideOf(b, c, d))) {
    return SegmentContact::kProper;
  }
  if (PointSegmentDistance(c, a, b) <= kEps || PointSegmentDistance(d, a, b) <= kEps ||
      PointSegmentDistance(a, c, d) <= kEps || PointSegmentDistance(b, c, d) <= kEps) {
    return SegmentContact::kTouching;
  }
  return SegmentContact::kNone;
}

double SegmentSegmentDistance(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (SegmentsIntersect(a, b, c, d)) return 0.0;
  return std::min({PointSegmentDistance(a, c, d), PointSegmentDistance(b, c, d),
                   PointSegmentDistance(c, a, b), PointSegmentDistance(d, a, b)});
}

PointLocation LocatePoint(const Point2& p, const std::vector<Point2>& polygon) {
  bool inside = false;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[j];
    const Point2& b = polygon[i];
    if (PointSegmentDistance(p, a, b) <= kEps) return PointLocation::kBoundary;
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside ? PointLocation::kInside : PointLocation::kOutside;
}

double SignedDistanceToPolygon(const Point2& p, const std::vector<Point2>& polygon) {
  double best = std::numeric_limits<double>::infinity();
  bool inside = false;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[j];
    const Point2& b = polygon[i];
    best = std::min(best, PointSegmentDistance(p, a, b));
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  if (!inside) return best;
  return best <= kEps ? 0.0 : -best;  // on the boundary, as LocatePoint decides
}

namespace {

// Parameters along a-b (in [0, 1], sorted, 0 and 1 included) where the segment meets the
// polygon's boundary; between two consecutive ones the segment is wholly inside or wholly
// outside. Returns false, leaving `contacts` partial, when a proper crossing is found and
// stop_at_crossing is set.
bool BoundaryContacts(const Point2& a, const Point2& b, const std::vector<Point2>& polygon,
                      bool stop_at_crossing, std::vector<double>& contacts) {
  contacts.clear();
  contacts.push_back(0.0);
  contacts.push_back(1.0);
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& c = polygon[j];
    const Point2& d = polygon[i];
    switch (SegmentIntersection(a, b, c, d)) {
      case SegmentContact::kNone:
        break;
      case SegmentContact::kProper:
        if (stop_at_crossing) return false;
        contacts.push_back(std::clamp(Cross(c - a, d - c) / Cross(b - a, d - c), 0.0, 1.0));
        break;
      case SegmentContact::kTouching:
        if (PointSegmentDistance(c, a, b) <= kEps) contacts.push_back(ProjectionParameter(c, a, b));
        if (PointSegmentDistance(d, a, b) <= kEps) contacts.push_back(ProjectionParameter(d, a, b));
        break;
    }
  }
  std::sort(contacts.begin(), contacts.end());
  return true;
}

}  // namespace

double SegmentPolygonDistance(const Point2& a, const Point2& b,
                              const std::vector<Point2>& polygon) {
  thread_local std::vector<double> contacts;
  BoundaryContacts(a, b, polygon, /*stop_at_crossing=*/false, contacts);
  const double da = SignedDistanceToPolygon(a, polygon);
  const double db = SignedDistanceToPolygon(b, polygon);
  if (contacts.size() == 2 && da > 0) {
    // Wholly outside: the closest pair involves an endpoint of one of the segments.
    double best = std::min(da, db);
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) best = std::min(best, PointSegmentDistance(polygon[i], a, b));
    return best;
  }
  // Meets the polygon: the smallest signed distance at the endpoints and at the middles of the
  // stretches between boundary contacts (negative exactly when some stretch is inside).
  double best = std::min({0.0, da, db});
  for (size_t i = 0; i + 1 < contacts.size(); ++i) {
    if (contacts[i + 1] - contacts[i] <= 0.0) continue;
    const Point2 mid = a + 0.5 * (contacts[i] + contacts[i + 1]) * (b - a);
    best = std::min(best, SignedDistanceToPolygon(mid, polygon));
  }
  return best;
}

double SegmentCircleDistance(const Point2& a, const Point2& b, const Circle& circle) {
  return PointSegmentDistance(circle.center, a, b) - circle.radius;
}

bool SegmentCrossesPolygonInterior(const Point2& a, const Point2& b,
                                   const std::vector<Point2>& polygon) {
  if ((b - a).norm() <= kEps) return LocatePoint(a, polygon) == PointLocation::kInside;
  thread_local std::vector<double> contacts;
  if (!BoundaryContacts(a, b, polygon, /*stop_at_crossing=*/true, contacts)) return true;
  const double min_gap = kEps / (b - a).norm();
  for (size_t i = 0; i + 1 < contacts.size(); ++i) {
    if (contacts[i + 1] - contacts[i] <= min_gap) continue;
    const Point2 mid = a + 0.5 * (contacts[i] + contacts[i + 1]) * (b - a);
    if (LocatePoint(mid, polygon) == PointLocation::kInside) return true;
  }
  return false;
}

bool StrictlyInsideConvex(const Point2& p, const std::vector<Point2>& convex) {
  const size_t n = convex.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    if (SideOf(p, convex[j], convex[i]) <= kEps) return false;
  }
  return true;
}

bool SegmentCrossesConvexInterior(const Point2& a, const Point2& b,
                                  const std::vector<Point2>& convex) {
  // Clip a + t (b - a) to the part more than kEps inside every edge (Cyrus-Beck).
  double t0 = 0.0, t1 = 1.0;
  const size_t n = convex.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const double sa = SideOf(a, convex[j], convex[i]) - kEps;
    const double sb = SideOf(b, convex[j], convex[i]) - kEps;
    if (sa <= 0 && sb <= 0) return false;
    if (sa < 0) t0 = std::max(t0, sa / (sa - sb));
    if (sb < 0) t1 = std::min(t1, sa / (sa - sb));
    if (t0 >= t1) return false;
  }
  return (t1 - t0) * (b - a).norm() > kEps || (b - a).norm() <= kEps;
}

Polygon CircleToPolygon(const Circle& circle, double tolerance) {
  constexpr int kMaxSides = 4096;
  int sides = kMaxSides;
  if (tolerance > 0) {
    const double half_angle = std::acos(circle.radius / (circle.radius + tolerance));
    if (half_angle > 0) {
      sides =
          static_cast<int>(std::min<double>(kMaxSides, std::ceil(std::numbers::pi / half_angle)));
    }
  }
  sides = std::max(sides, 6);
  const double reach = circle.radius / std::cos(std::numbers::pi / sides);
  Polygon out;
  out.vertices.reserve(sides);
  for (int k = 0; k < sides; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / sides;
    out.vertices.push_back(circle.center + reach * Point2(std::cos(phi), std::sin(phi)));
  }
  return out;
}

Bounds2 BoundingBox(const std::vector<Point2>& points) {
  Bounds2 box;
  if (points.empty()) return box;
  box.min = box.max = points.front();
  for (const Point2& p : points) {
    box.min = box.min.cwiseMin(p);
    box.max = box.max.cwiseMax(p);
  }
  return box;
}

// The gaps between two boxes along x and along y (0 where they overlap).
static Point2 BoxGaps(const Bounds2& a, const Bounds2& b) {
  return Point2(std::max({0.0, a.min.x() - b.max.x(), b.min.x() - a.max.x()}),
                std::max({0.0, a.min.y() - b.max.y(), b.min.y() - a.max.y()}));
}

double BoxDistance(const Bounds2& a, const Bounds2& b) {
  const Point2 gap = BoxGaps(a, b);
  return std::hypot(gap.x(), gap.y());
}

bool BoxesFartherThan(const Bounds2& a, const Bounds2& b, double d) {
  return d < 0 || BoxGaps(a, b).squaredNorm() > d * d * (1.0 + 1e-12);
}

bool IsConvex(const std::vector<Point2>& polygon) {
  const std::vector<Point2> v = WithoutDuplicates(polygon);
  const size_t n = v.size();
  for (size_t i = 0; i < n; ++i) {
    if (SideOf(v[(i + 1) % n], v[(i + n - 1) % n], v[i]) < -kEps) return false;
  }
  return true;
}

std::vector<Polygon> Triangulate(const Polygon& polygon) {
  std::vector<Point2> v = WithoutCollinear(WithoutDuplicates(polygon.vertices));
  std::vector<Polygon> triangles;
  while (v.size() > 3) {
    const size_t n = v.size();
    bool clipped = false;
    for (size_t i = 0; i < n && !clipped; ++i) {
      const Point2& prev = v[(i + n - 1) % n];
      const Point2& cur = v[i];
      const Point2& next = v[(i + 1) % n];
      if (SideOf(next, prev, cur) <= kEps) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (size_t k = 0; k < n && empty; ++k) {
        if (k == i || k == (i + 1) % n || k == (i + n - 1) % n) continue;
        empty = !InTriangle(v[k], prev, cur, next);
      }
      if (!empty) continue;
      triangles.push_back(Polygon{{prev, cur, next}});
      v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
      v = WithoutCollinear(std::move(v));
      clipped = true;
    }
    if (!clipped) {
      // Numerically degenerate remainder: cover it by its bounding box (conservative).
      const Bounds2 box = BoundingBox(v);
      triangles.push_back(
          Polygon{{box.min, {box.max.x(), box.min.y()}, box.max, {box.min.x(), box.max.y()}}});
      return triangles;
    }
  }
  if (v.size() == 3) triangles.push_back(Polygon{v});
  return triangles;
}

std::vector<Polygon> GrowPolygon(const Polygon& polygon, double radius, double tolerance) {
  if (radius <= 0) return {polygon};
  const std::vector<Point2> v = WithoutCollinear(WithoutDuplicates(polygon.vertices));
  if (IsConvex(v)) return {GrowConvex(v, radius, tolerance)};
  std::vector<Polygon> pieces;
  for (const Polygon& t : Triangulate(Polygon{v})) {
    pieces.push_back(GrowConvex(t.vertices, radius, tolerance));
  }
  return pieces;
}

}  // namespace swarmplan
