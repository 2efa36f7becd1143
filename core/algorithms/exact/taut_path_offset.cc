#include "core/algorithms/exact/taut_path_offset.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "core/geometry/grid_collision.h"

namespace swarmplan {
namespace {

// Distance (cells) below which a lattice point counts as lying on a segment.
constexpr double kOnSegment = 1e-9;
constexpr int kOffsetRepairRounds = 3;

bool BlockedInGrid(const OccupancyGrid& grid, int x, int y) {
  return grid.InBounds(x, y) && grid.IsBlocked(x, y);
}

// The direction (components -1, 0, 1) away from the blocked cells around lattice point p;
// zero when none is blocked or they balance (two cells touching at a corner).
Point2 AwayFromBlocked(const OccupancyGrid& grid, const Point2& p) {
  const int x = static_cast<int>(p.x()), y = static_cast<int>(p.y());
  Point2 sum = Point2::Zero();
  for (int dy = -1; dy <= 0; ++dy) {
    for (int dx = -1; dx <= 0; ++dx) {
      if (BlockedInGrid(grid, x + dx, y + dy)) sum += Point2(dx == 0 ? -1 : 1, dy == 0 ? -1 : 1);
    }
  }
  return Point2((sum.x() > 0) - (sum.x() < 0), (sum.y() > 0) - (sum.y() < 0));
}

bool TouchesBlocked(const OccupancyGrid& grid, const Point2& p) {
  const int x = static_cast<int>(p.x()), y = static_cast<int>(p.y());
  return BlockedInGrid(grid, x - 1, y - 1) || BlockedInGrid(grid, x, y - 1) ||
         BlockedInGrid(grid, x - 1, y) || BlockedInGrid(grid, x, y);
}

// Lattice points touching a blocked cell within `tol` of the open segment u-v, ordered from u.
std::vector<Point2> LatticePointsNear(const OccupancyGrid& grid, const Point2& u, const Point2& v,
                                      double tol) {
  std::vector<std::pair<double, Point2>> found;
  const Point2 d = v - u;
  const double len2 = d.squaredNorm();
  if (len2 == 0.0) return {};
  // Walk the integer values of the dominant axis; the other coordinate spans a window.
  const int major = std::abs(d.x()) >= std::abs(d.y()) ? 0 : 1;
  const int minor = 1 - major;
  const double slope = d[minor] / d[major];
  const double window = tol * std::sqrt(1 + slope * slope) + tol;
  const int first = static_cast<int>(std::ceil(std::min(u[major], v[major]) - tol));
  const int last = static_cast<int>(std::floor(std::max(u[major], v[major]) + tol));
  for (int m = first; m <= last; ++m) {
    const double at = u[minor] + (m - u[major]) * slope;
    for (int n = static_cast<int>(std::ceil(at - window));
         n <= static_cast<int>(std::floor(at + window)); ++n) {
      Point2 p;
      p[major] = m;
      p[minor] = n;
      const double t = (p - u).dot(d) / len2;
      if (t <= 0.0 || t >= 1.0) continue;
      if ((u + t * d - p).norm() > tol) continue;
      if ((p - u).norm() <= tol || (p - v).norm() <= tol) continue;
      if (TouchesBlocked(grid, p)) found.emplace_back(t, p);
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Point2> points;
  for (const auto& [t, p] : found) points.push_back(p);
  return points;
}

}  // namespace

absl::StatusOr<std::vector<Point2>> OffsetTautPath(const OccupancyGrid& grid,
                                                   const std::vector<Point2>& vertices,
                                                   double offset) {
  if (vertices.size() < 2) return vertices;
  const GridCollisionChecker checker(grid);
  // base: the touching path; moved: its vertices after the offset.
  std::vector<Point2> base = {vertices.front()};
  for (size_t i = 0; i + 1 < vertices.size(); ++i) {
    for (const Point2& p : LatticePointsNear(grid, vertices[i], vertices[i + 1], kOnSegment)) {
      base.push_back(p);
    }
    base.push_back(vertices[i + 1]);
  }
  const auto move = [&](const std::vector<Point2>& points) {
    std::vector<Point2> moved = points;
    for (size_t i = 1; i + 1 < moved.size(); ++i) {
      if (points[i] == points[i].array().floor().matrix()) {
        moved[i] += offset * AwayFromBlocked(grid, points[i]);
      }
    }
    return moved;
  };
  for (int round = 0;; ++round) {
    const std::vector<Point2> moved = move(base);
    std::vector<Point2> repaired = {base.front()};
    bool all_free = true;
    for (size_t i = 0; i + 1 < moved.size(); ++i) {
      if (!checker.TraversalFree(moved[i], moved[i + 1])) {
        all_free = false;
        if (round == kOffsetRepairRounds) {
          return absl::InternalError(
              absl::StrCat("exact any-angle path: segment ", i, " from (", moved[i].x(), ", ",
                           moved[i].y(), ") to (", moved[i + 1].x(), ", ", moved[i + 1].y(),
                           ") (grid coordinates) still touches a blocked cell after the offset"));
        }
        // A near miss of another corner: that corner becomes a vertex too.
        for (const Point2& p : LatticePointsNear(grid, moved[i], moved[i + 1], 4 * offset)) {
          repaired.push_back(p);
        }
      }
      repaired.push_back(base[i + 1]);
    }
    if (all_free) return moved;
    base = std::move(repaired);
  }
}

}  // namespace swarmplan
