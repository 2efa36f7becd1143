#include "core/algorithms/exact/clearance_repair.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarmplan {
namespace {

constexpr int kPushRounds = 8;
constexpr int kTightenSweeps = 2;
constexpr int kTightenSteps = 6;
constexpr int kSplitLevels = 24;
constexpr size_t kMaxPoints = 1 << 14;
// Spacing (cells) of the samples among which a segment that comes too close is split.
constexpr double kSplitSpacing = 1.0 / 16.0;

// The point of the blocked squares of `grid` nearest to `p` (world units) among those within
// `reach`, or none.
std::optional<Point2> NearestBlockedPoint(const OccupancyGrid& grid, const Point2& p,
                                          double reach) {
  const double res = grid.resolution();
  const Point2 u = (p - grid.origin()) / res;
  const int span = static_cast<int>(std::ceil(reach / res)) + 1;
  const int cx = static_cast<int>(std::floor(u.x())), cy = static_cast<int>(std::floor(u.y()));
  std::optional<Point2> best;
  double best_squared = std::numeric_limits<double>::infinity();
  for (int y = std::max(0, cy - span); y <= std::min(grid.height() - 1, cy + span); ++y) {
    for (int x = std::max(0, cx - span); x <= std::min(grid.width() - 1, cx + span); ++x) {
      if (!grid.IsBlocked(x, y)) continue;
      const Point2 q(std::clamp(u.x(), static_cast<double>(x), x + 1.0),
                     std::clamp(u.y(), static_cast<double>(y), y + 1.0));
      const double squared = (q - u).squaredNorm();
      if (squared < best_squared) {
        best_squared = squared;
        best = q;
      }
    }
  }
  if (!best) return std::nullopt;
  return grid.origin() + *best * res;
}

class ClearanceRepair {
 public:
  ClearanceRepair(const OccupancyGrid& grid, const CollisionChecker& exact, double clearance)
      : grid_(grid),
        exact_(exact),
        clearance_(clearance),
        target_(clearance * (1.0 + 1e-3) + 1e-9 * grid.resolution()),
        accept_(clearance * (1.0 + 5e-4)) {}

  // `p` moved away from the blocked squares until it keeps target_ from them, or none.
  std::optional<Point2> Push(Point2 p) const {
    for (int round = 0; round < kPushRounds; ++round) {
      const std::optional<Point2> q = NearestBlockedPoint(grid_, p, target_);
      if (!q) return p;
      const Point2 away = p - *q;
      const double distance = away.norm();
      if (distance >= accept_) return p;
      if (distance == 0.0) return std::nullopt;
      p = *q + away * (target_ / distance);
    }
    return std::nullopt;
  }

  bool Free(const Point2& a, const Point2& b) const {
    return exact_.SegmentFree(Point3(a.x(), a.y(), 0.0), Point3(b.x(), b.y(), 0.0), clearance_);
  }

  // Appends to `out` the points after `a` that lead to `b` keeping the clearance: a segment
  // that comes too close is split where it comes closest (of samples kSplitSpacing apart), at
  // that point moved off the obstacles.
  bool Join(const Point2& a, const Point2& b, int levels, std::vector<Point2>& out) const {
    if (Free(a, b)) {
      out.push_back(b);
      return true;
    }
    const int samples = std::max(
        2, static_cast<int>(std::ceil((b - a).norm() / (kSplitSpacing * grid_.resolution()))));
    if (levels == 0 || out.size() >= kMaxPoints) return false;
    Point2 closest = a;
    double least = std::numeric_limits<double>::infinity();
    for (int i = 1; i < samples; ++i) {
      const Point2 p = a + (b - a) * (static_cast<double>(i) / samples);
      const double kept = exact_.Clearance(Point3(p.x(), p.y(), 0.0));
      if (kept < least) {
        least = kept;
        closest = p;
      }
    }
    const std::optional<Point2> middle = Push(closest);
    if (!middle || *middle == a || *middle == b) return false;
    return Join(a, *middle, levels - 1, out) && Join(*middle, b, levels - 1, out);
  }

  // String pulling: from each kept point, on to the last of the points after it that it sees
  // one after another.
  std::vector<Point2> Pull(const std::vector<Point2>& points) const {
    std::vector<Point2> pulled = {points.front()};
    size_t anchor = 0;
    while (anchor + 1 < points.size()) {
      size_t next = anchor + 1;
      while (next + 1 < points.size() && Free(points[anchor], points[next + 1])) ++next;
      pulled.push_back(points[next]);
      anchor = next;
    }
    return pulled;
  }

  // Moves each inner point toward the middle of its neighbours as far as (by bisection) both
  // its segments keep the clearance: takes up the slack the pushes left.
  void Tighten(std::vector<Point2>& points) const {
    for (int sweep = 0; sweep < kTightenSweeps; ++sweep) {
      for (size_t i = 1; i + 1 < points.size(); ++i) {
        const Point2 from = points[i];
        const Point2 toward = 0.5 * (points[i - 1] + points[i + 1]);
        double kept = 0.0, step = 1.0;
        for (int k = 0; k < kTightenSteps; ++k, step *= 0.5) {
          const Point2 moved = from + (kept + step) * (toward - from);
          if (Free(points[i - 1], moved) && Free(moved, points[i + 1])) kept += step;
        }
        points[i] = from + kept * (toward - from);
      }
    }
  }

 private:
  const OccupancyGrid& grid_;
  const CollisionChecker& exact_;
  double clearance_;
  double target_;  // where a point moves to
  double accept_;  // what a point must keep: below target_, so that rounding cannot fail a move
};

}  // namespace

std::optional<std::vector<Point2>> RepairToClearance(const OccupancyGrid& grid,
                                                     const CollisionChecker& exact,
                                                     const std::vector<Point2>& vertices,
                                                     double clearance) {
  if (vertices.size() < 2) return std::nullopt;
  const ClearanceRepair repair(grid, exact, clearance);
  std::vector<Point2> pushed = {vertices.front()};
  for (size_t i = 1; i + 1 < vertices.size(); ++i) {
    const std::optional<Point2> p = repair.Push(vertices[i]);
    if (!p) return std::nullopt;
    pushed.push_back(*p);
  }
  pushed.push_back(vertices.back());
  std::vector<Point2> joined = {pushed.front()};
  for (size_t i = 1; i < pushed.size(); ++i) {
    if (!repair.Join(joined.back(), pushed[i], kSplitLevels, joined)) return std::nullopt;
  }
  std::vector<Point2> pulled = repair.Pull(joined);
  repair.Tighten(pulled);
  return pulled;
}

}  // namespace swarmplan
