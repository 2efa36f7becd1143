#include "core/geometry/homotopy.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

std::vector<Point2> Loop(const Path& a, const Path& b) {
  std::vector<Point2> loop;
  for (const Point3& p : a) loop.emplace_back(p.x(), p.y());
  for (auto it = b.rbegin(); it != b.rend(); ++it) loop.emplace_back(it->x(), it->y());
  return loop;
}

// The winding number of the closed polygon `loop` around p (crossings of the ray to +x).
int WindingNumber(const std::vector<Point2>& loop, const Point2& p) {
  int winding = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Point2& u = loop[i];
    const Point2& v = loop[(i + 1) % loop.size()];
    const double side = (v.x() - u.x()) * (p.y() - u.y()) - (p.x() - u.x()) * (v.y() - u.y());
    if (u.y() <= p.y() && v.y() > p.y() && side > 0) ++winding;
    if (u.y() > p.y() && v.y() <= p.y() && side < 0) --winding;
  }
  return winding;
}

// A point strictly inside the simple polygon: its vertex average when that is inside, else an
// edge midpoint moved a little inward.
Point2 InteriorPoint(const std::vector<Point2>& polygon) {
  Point2 mean = Point2::Zero();
  for (const Point2& v : polygon) mean += v;
  mean /= static_cast<double>(polygon.size());
  if (LocatePoint(mean, polygon) == PointLocation::kInside) return mean;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point2 u = polygon[i], v = polygon[(i + 1) % polygon.size()];
    const Point2 d = v - u;
    const Point2 normal = Point2(-d.y(), d.x()) * (1e-6 / std::max(d.norm(), 1e-300));
    const Point2 mid = 0.5 * (u + v);
    for (const Point2& candidate : {Point2(mid + normal), Point2(mid - normal)}) {
      if (LocatePoint(candidate, polygon) == PointLocation::kInside) return candidate;
    }
  }
  return polygon[0];
}

bool LoopEnclosesBlockedCell(const OccupancyGrid& grid, const std::vector<Point2>& loop) {
  // Row by row: the loop's crossings of the row's centre line, sorted, give the intervals of
  // non-zero winding; a blocked cell whose centre lies in one is enclosed.
  const double res = grid.resolution();
  double lo = loop[0].y(), hi = loop[0].y();
  for (const Point2& p : loop) {
    lo = std::min(lo, p.y());
    hi = std::max(hi, p.y());
  }
  const int first = std::max(0, static_cast<int>(std::floor((lo - grid.origin().y()) / res)));
  const int last =
      std::min(grid.height() - 1, static_cast<int>(std::ceil((hi - grid.origin().y()) / res)));
  std::vector<std::pair<double, int>> crossings;
  for (int row = first; row <= last; ++row) {
    const double y = grid.origin().y() + (row + 0.5) * res;
    crossings.clear();
    for (size_t i = 0; i < loop.size(); ++i) {
      const Point2& u = loop[i];
      const Point2& v = loop[(i + 1) % loop.size()];
      const bool up = u.y() <= y && v.y() > y, down = u.y() > y && v.y() <= y;
      if (!up && !down) continue;
      const double x = u.x() + (y - u.y()) * (v.x() - u.x()) / (v.y() - u.y());
      crossings.emplace_back(x, up ? 1 : -1);
    }
    std::sort(crossings.begin(), crossings.end());
    int winding = 0;
    for (size_t i = 0; i + 1 < crossings.size(); ++i) {
      winding += crossings[i].second;
      if (winding == 0) continue;
      // Cells whose centre lies in (crossings[i].x, crossings[i + 1].x).
      const double from = (crossings[i].first - grid.origin().x()) / res - 0.5;
      const double to = (crossings[i + 1].first - grid.origin().x()) / res - 0.5;
      const int x0 = std::max(0, static_cast<int>(std::floor(from)) + 1);
      const int x1 = std::min(grid.width() - 1, static_cast<int>(std::ceil(to)) - 1);
      for (int x = x0; x <= x1; ++x) {
        if (grid.IsBlocked(x, row)) return true;
      }
    }
  }
  return false;
}

}  // namespace

bool SeparatedByObstacle(const Map& map, const Path& a, const Path& b) {
  if (a.empty() || b.empty()) return false;
  const std::vector<Point2> loop = Loop(a, b);
  if (const OccupancyGrid* grid = map.grid()) return LoopEnclosesBlockedCell(*grid, loop);
  const ShapeWorld* world = map.world();
  if (world == nullptr) return false;
  for (const Circle& c : world->circles()) {
    if (WindingNumber(loop, c.center) != 0) return true;
  }
  for (const Polygon& polygon : world->polygons()) {
    if (WindingNumber(loop, InteriorPoint(polygon.vertices)) != 0) return true;
  }
  return false;
}

}  // namespace swarmplan
