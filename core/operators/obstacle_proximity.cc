#include "core/operators/obstacle_proximity.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "absl/status/status.h"
#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

bool BoxesOverlap(const Point2& amin, const Point2& amax, const Point2& bmin, const Point2& bmax) {
  return amin.x() <= bmax.x() && bmin.x() <= amax.x() && amin.y() <= bmax.y() &&
         bmin.y() <= amax.y();
}

}  // namespace

absl::StatusOr<ObstacleProximity> ObstacleProximity::Create(const Map& map, double threshold) {
  ObstacleProximity p;
  p.threshold_ = threshold;
  if (const ShapeWorld* world = map.world()) {
    p.world_ = world;
    p.lower_ = world->bounds().min;
    p.upper_ = world->bounds().max;
    for (const Polygon& poly : world->polygons()) {
      Point2 lo = poly.vertices[0], hi = poly.vertices[0];
      for (const Point2& v : poly.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      p.polygon_min_.push_back(lo);
      p.polygon_max_.push_back(hi);
    }
    p.obstacle_count_ = static_cast<int>(world->ObstacleCount());
    return p;
  }
  const OccupancyGrid* grid = map.grid();
  if (grid == nullptr) {
    return absl::FailedPreconditionError("obstacle proximity: needs a 2D map, not a terrain");
  }
  p.grid_ = grid;
  p.lower_ = grid->origin();
  p.upper_ = grid->origin() + Point2(grid->width(), grid->height()) * grid->resolution();
  const int w = grid->width(), h = grid->height();
  p.label_.assign(static_cast<size_t>(w) * h, -1);
  auto index = [w](int x, int y) { return static_cast<size_t>(y) * w + x; };
  // Components of blocked cells, 8-connected.
  std::deque<Cell> queue;
  int components = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!grid->IsBlocked(x, y) || p.label_[index(x, y)] >= 0) continue;
      p.label_[index(x, y)] = components;
      queue.push_back({x, y});
      while (!queue.empty()) {
        const Cell c = queue.front();
        queue.pop_front();
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = c.x + dx, ny = c.y + dy;
            if (!grid->InBounds(nx, ny) || !grid->IsBlocked(nx, ny)) continue;
            if (p.label_[index(nx, ny)] >= 0) continue;
            p.label_[index(nx, ny)] = components;
            queue.push_back({nx, ny});
          }
        }
      }
      ++components;
    }
  }
  // Sweep outward from every blocked cell through the cells closer than the threshold.
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (grid->IsBlocked(x, y)) queue.push_back({x, y});
    }
  }
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = c.x + dx, ny = c.y + dy;
        if (!grid->InBounds(nx, ny) || p.label_[index(nx, ny)] >= 0) continue;
        if (grid->DistanceToObstacle(nx, ny) >= threshold) continue;
        p.label_[index(nx, ny)] = p.label_[index(c.x, c.y)];
        queue.push_back({nx, ny});
      }
    }
  }
  p.obstacle_count_ = components;
  p.seen_stamp_.assign(components, 0);
  return p;
}

int ObstacleProximity::CountViolations(const Path& path) {
  return world_ != nullptr ? CountOnWorld(path) : CountOnGrid(path);
}

int ObstacleProximity::CountOnWorld(const Path& path) const {
  if (path.empty()) return 0;
  int count = 0;
  Point2 path_min = path[0].head<2>(), path_max = path_min;
  bool outside = false;
  for (const Point3& q : path) {
    const Point2 p = q.head<2>();
    path_min = path_min.cwiseMin(p);
    path_max = path_max.cwiseMax(p);
    outside = outside || p.x() < lower_.x() || p.y() < lower_.y() || p.x() > upper_.x() ||
              p.y() > upper_.y();
  }
  if (outside) ++count;
  const Point2 margin(threshold_, threshold_);
  const size_t segments = path.size() > 1 ? path.size() - 1 : 1;
  for (const Circle& circle : world_->circles()) {
    const Point2 cmin = circle.center.array() - circle.radius - threshold_;
    const Point2 cmax = circle.center.array() + circle.radius + threshold_;
    if (!BoxesOverlap(path_min, path_max, cmin, cmax)) continue;
    for (size_t i = 0; i < segments; ++i) {
      const Point2 a = path[i].head<2>();
      const Point2 b = path[std::min(i + 1, path.size() - 1)].head<2>();
      if (!BoxesOverlap(a.cwiseMin(b), a.cwiseMax(b), cmin, cmax)) continue;
      if (SegmentCircleDistance(a, b, circle) < threshold_) {
        ++count;
        break;
      }
    }
  }
  const auto& polygons = world_->polygons();
  for (size_t k = 0; k < polygons.size(); ++k) {
    const Point2 pmin = polygon_min_[k] - margin, pmax = polygon_max_[k] + margin;
    if (!BoxesOverlap(path_min, path_max, pmin, pmax)) continue;
    for (size_t i = 0; i < segments; ++i) {
      const Point2 a = path[i].head<2>();
      const Point2 b = path[std::min(i + 1, path.size() - 1)].head<2>();
      if (!BoxesOverlap(a.cwiseMin(b), a.cwiseMax(b), pmin, pmax)) continue;
      if (SegmentPolygonDistance(a, b, polygons[k].vertices) < threshold_) {
        ++count;
        break;
      }
    }
  }
  return count;
}

int ObstacleProximity::CountOnGrid(const Path& path) {
  if (path.empty()) return 0;
  if (++stamp_ == 0) {  // wrapped: forget every mark
    std::fill(seen_stamp_.begin(), seen_stamp_.end(), 0);
    stamp_ = 1;
  }
  int count = 0;
  bool outside = false;
  const double res = grid_->resolution();
  const double inv_res = 1.0 / res;
  const Point2 origin = grid_->origin();
  const int w = grid_->width(), h = grid_->height();
  auto visit = [&](const Point2& p) {
    const int cx = static_cast<int>(std::floor((p.x() - origin.x()) * inv_res));
    const int cy = static_cast<int>(std::floor((p.y() - origin.y()) * inv_res));
    if (cx < 0 || cy < 0 || cx >= w || cy >= h) {
      outside = true;
      return;
    }
    const int32_t label = label_[static_cast<size_t>(cy) * w + cx];
    if (label >= 0 && seen_stamp_[label] != stamp_) {
      seen_stamp_[label] = stamp_;
      ++count;
    }
  };
  visit(path[0].head<2>());
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Point2 a = path[i].head<2>(), b = path[i + 1].head<2>();
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() * 4.0 * inv_res)));
    for (int s = 1; s <= steps; ++s) visit(a + (b - a) * (static_cast<double>(s) / steps));
  }
  return count + (outside ? 1 : 0);
}

}  // namespace swarmplan
