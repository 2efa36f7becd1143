#pragma once

// Collision checks written for the planner contract test, independent of core/geometry: exact
// segment-to-square distances on grids, exact segment distances to circles and polygons on
// shape worlds. A planner's path is judged by these, never by its own checker.

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/map/map.h"
#include "core/map/point.h"

namespace swarmplan::contract {

inline double PointSegmentDistance(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Whether segments ab and cd share a point (touching counts).
inline bool SegmentsIntersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  auto cross = [](const Point2& o, const Point2& p, const Point2& q) {
    return (p.x() - o.x()) * (q.y() - o.y()) - (p.y() - o.y()) * (q.x() - o.x());
  };
  auto on_segment = [](const Point2& p, const Point2& q, const Point2& r) {
    return std::min(p.x(), r.x()) <= q.x() && q.x() <= std::max(p.x(), r.x()) &&
           std::min(p.y(), r.y()) <= q.y() && q.y() <= std::max(p.y(), r.y());
  };
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  return (d1 == 0 && on_segment(c, a, d)) || (d2 == 0 && on_segment(c, b, d)) ||
         (d3 == 0 && on_segment(a, c, b)) || (d4 == 0 && on_segment(a, d, b));
}

inline double SegmentSegmentDistance(const Point2& a, const Point2& b, const Point2& c,
                                     const Point2& d) {
  if (SegmentsIntersect(a, b, c, d)) return 0.0;
  return std::min({PointSegmentDistance(a, c, d), PointSegmentDistance(b, c, d),
                   PointSegmentDistance(c, a, b), PointSegmentDistance(d, a, b)});
}

inline bool InsidePolygon(const Point2& p, const Polygon& polygon) {
  bool inside = false;
  const std::vector<Point2>& v = polygon.vertices;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Distance from segment ab to the closed polygon (0 when they meet or ab lies inside).
inline double SegmentPolygonDistance(const Point2& a, const Point2& b, const Polygon& polygon) {
  if (InsidePolygon(a, polygon)) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  const std::vector<Point2>& v = polygon.vertices;
  for (size_t i = 0; i < v.size(); ++i) {
    d = std::min(d, SegmentSegmentDistance(a, b, v[i], v[(i + 1) % v.size()]));
  }
  return d;
}

// Distance from segment ab to the closed axis-aligned square [lo, hi].
inline double SegmentBoxDistance(const Point2& a, const Point2& b, const Point2& lo,
                                 const Point2& hi) {
  const Point2 corners[4] = {lo, Point2(hi.x(), lo.y()), hi, Point2(lo.x(), hi.y())};
  Polygon box;
  box.vertices.assign(std::begin(corners), std::end(corners));
  auto inside = [&](const Point2& p) {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
  };
  if (inside(a) || inside(b)) return 0.0;
  return SegmentPolygonDistance(a, b, box);
}

// The largest curvature of the circle through each three consecutive points of the path.
inline double LargestMengerCurvature(const Path& path) {
  double largest = 0.0;
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    const Point2 a = path[i - 1].head<2>(), b = path[i].head<2>(), c = path[i + 1].head<2>();
    const double twice_area = std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    const double product = (b - a).norm() * (c - b).norm() * (c - a).norm();
    if (product > 0) largest = std::max(largest, 2.0 * twice_area / product);
  }
  return largest;
}

// The smallest distance from the path to a blocked cell square of the grid; -1 when a point
// leaves the grid.
inline double GridPathClearance(const OccupancyGrid& grid, const Path& path) {
  const double r = grid.resolution();
  const Point2 origin = grid.origin();
  const Point2 grid_max = origin + Point2(grid.width(), grid.height()) * r;
  double clearance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Point2 a = path[i].head<2>(), b = path[i + 1].head<2>();
    for (const Point2& p : {a, b}) {
      if (p.x() < origin.x() || p.y() < origin.y() || p.x() > grid_max.x() ||
          p.y() > grid_max.y()) {
        return -1.0;
      }
    }
    // Only squares within the current best distance of the segment's box can lower it.
    const double reach = std::isfinite(clearance) ? clearance : 3.0 * r;
    const int x0 = static_cast<int>(std::floor((std::min(a.x(), b.x()) - reach - origin.x()) / r));
    const int x1 = static_cast<int>(std::floor((std::max(a.x(), b.x()) + reach - origin.x()) / r));
    const int y0 = static_cast<int>(std::floor((std::min(a.y(), b.y()) - reach - origin.y()) / r));
    const int y1 = static_cast<int>(std::floor((std::max(a.y(), b.y()) + reach - origin.y()) / r));
    for (int y = std::max(y0, 0); y <= std::min(y1, grid.height() - 1); ++y) {
      for (int x = std::max(x0, 0); x <= std::min(x1, grid.width() - 1); ++x) {
        if (!grid.IsBlocked(x, y)) continue;
        const Point2 lo = origin + Point2(x, y) * r;
        clearance = std::min(clearance, SegmentBoxDistance(a, b, lo, lo + Point2(r, r)));
      }
    }
  }
  return clearance;
}

// The smallest distance from the path to an obstacle of the world; -1 when a point leaves the
// bounds.
inline double WorldPathClearance(const ShapeWorld& world, const Path& path) {
  double clearance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Point2 a = path[i].head<2>(), b = path[i + 1].head<2>();
    if (!world.bounds().Contains(a) || !world.bounds().Contains(b)) return -1.0;
    for (const Circle& c : world.circles()) {
      clearance = std::min(clearance, PointSegmentDistance(c.center, a, b) - c.radius);
    }
    for (const Polygon& polygon : world.polygons()) {
      clearance = std::min(clearance, SegmentPolygonDistance(a, b, polygon));
    }
  }
  return clearance;
}

// The smallest height of the path above the terrain's ground, from the terrain's own samples
// (bilinear between cell centres, computed here) every 1/50 of a cell along each segment; -1
// when a point leaves the terrain, flies over a cell without data or above the ceiling.
inline double TerrainPathClearance(const Terrain& terrain, const Path& path) {
  auto ground = [&](const Point2& world) {
    const Point2 c = terrain.ToCell(world);
    if (c.x() < -1e-9 || c.y() < -1e-9 || c.x() > terrain.width() - 1 + 1e-9 ||
        c.y() > terrain.depth() - 1 + 1e-9) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    const int x0 = std::clamp(static_cast<int>(std::floor(c.x())), 0, terrain.width() - 2);
    const int y0 = std::clamp(static_cast<int>(std::floor(c.y())), 0, terrain.depth() - 2);
    const double fx = c.x() - x0, fy = c.y() - y0;
    return (1 - fx) * (1 - fy) * terrain.HeightAt(x0, y0) +
           fx * (1 - fy) * terrain.HeightAt(x0 + 1, y0) +
           (1 - fx) * fy * terrain.HeightAt(x0, y0 + 1) +
           fx * fy * terrain.HeightAt(x0 + 1, y0 + 1);
  };
  double clearance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Point3& a = path[i];
    const Point3& b = path[i + 1];
    const double cells = (b - a).head<2>().norm() / terrain.cell_size();
    const int steps = std::max(1, static_cast<int>(std::ceil(cells * 50)));
    for (int k = 0; k <= steps; ++k) {
      const Point3 p = a + (b - a) * (static_cast<double>(k) / steps);
      const double g = ground(p.head<2>());
      if (std::isnan(g) || p.z() > terrain.ceiling() + 1e-9) return -1.0;
      clearance = std::min(clearance, p.z() - g);
    }
  }
  return clearance;
}

}  // namespace swarmplan::contract
