#include "core/grid_ops/grid_moves.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/graph/grid_search.h"

namespace swarmplan {
namespace {

std::vector<Cell> MakeOffsets(int reach, bool diagonals) {
  std::vector<Cell> out;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      if (dx == 0 && dy == 0) continue;
      if (!diagonals && dx != 0 && dy != 0) continue;
      if (!diagonals && (std::abs(dx) > 1 || std::abs(dy) > 1)) continue;
      out.push_back(Cell{dx, dy});
    }
  }
  return out;
}

// Signed area test on doubled integer coordinates: exact.
int64_t Side(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

double PointSegmentDistance(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len2 = ab.squaredNorm();
  double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * ab - p).norm();
}

double PointBoxDistance(const Point2& p, const Point2& lo, const Point2& hi) {
  const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
  const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
  return std::hypot(dx, dy);
}

}  // namespace

const std::vector<Cell>& MoveOffsets(Neighbourhood neighbourhood) {
  static const std::vector<Cell> k4 = MakeOffsets(1, false);
  static const std::vector<Cell> k8 = MakeOffsets(1, true);
  static const std::vector<Cell> k24 = MakeOffsets(2, true);
  switch (neighbourhood) {
    case Neighbourhood::k4:
      return k4;
    case Neighbourhood::k8:
      return k8;
    case Neighbourhood::k24:
      return k24;
  }
  return k8;
}

std::vector<Cell> CellsTouchedBySegment(Cell a, Cell b) {
  // Doubled coordinates: centres are odd integers, cell (x, y) spans [2x, 2x + 2].
  const int64_t ax = 2 * int64_t{a.x} + 1, ay = 2 * int64_t{a.y} + 1;
  const int64_t bx = 2 * int64_t{b.x} + 1, by = 2 * int64_t{b.y} + 1;
  std::vector<Cell> out;
  for (int y = std::min(a.y, b.y); y <= std::max(a.y, b.y); ++y) {
    for (int x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x) {
      const int64_t x0 = 2 * int64_t{x}, y0 = 2 * int64_t{y}, x1 = x0 + 2, y1 = y0 + 2;
      const int64_t s[4] = {Side(ax, ay, bx, by, x0, y0), Side(ax, ay, bx, by, x1, y0),
                            Side(ax, ay, bx, by, x0, y1), Side(ax, ay, bx, by, x1, y1)};
      const bool all_pos = s[0] > 0 && s[1] > 0 && s[2] > 0 && s[3] > 0;
      const bool all_neg = s[0] < 0 && s[1] < 0 && s[2] < 0 && s[3] < 0;
      if (!all_pos && !all_neg) out.push_back(Cell{x, y});
    }
  }
  return out;
}

double SegmentBoxDistance(const Point2& a, const Point2& b, const Point2& lo, const Point2& hi) {
  // Intersection: Liang-Barsky clipping of the segment against the box.
  double t0 = 0.0, t1 = 1.0;
  const Point2 d = b - a;
  bool meets = true;
  for (int axis = 0; axis < 2 && meets; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) meets = false;
    } else {
      double ta = (lo[axis] - a[axis]) / d[axis];
      double tb = (hi[axis] - a[axis]) / d[axis];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (t0 > t1) meets = false;
    }
  }
  if (meets) return 0.0;
  double best = std::min(PointBoxDistance(a, lo, hi), PointBoxDistance(b, lo, hi));
  const Point2 corners[4] = {lo, Point2(hi.x(), lo.y()), Point2(lo.x(), hi.y()), hi};
  for (const Point2& c : corners) best = std::min(best, PointSegmentDistance(c, a, b));
  return best;
}

GridMoves::GridMoves(const OccupancyGrid& grid, MoveRules rules) : grid_(&grid), rules_(rules) {
  const size_t n = static_cast<size_t>(grid.width()) * grid.height();
  usable_.assign(n, 0);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      usable_[Index(Cell{x, y})] = CellUsable(grid, Cell{x, y}, rules.clearance) ? 1 : 0;
    }
  }
  moves_.resize(n);
  moves_known_.assign(n, 0);
}

bool GridMoves::IsMove(Cell from, Cell to) const {
  const int dx = to.x - from.x, dy = to.y - from.y;
  const int reach = std::max(std::abs(dx), std::abs(dy));
  if (reach == 0) return false;
  switch (rules_.neighbourhood) {
    case Neighbourhood::k4:
      if (std::abs(dx) + std::abs(dy) != 1) return false;
      break;
    case Neighbourhood::k8:
      if (reach != 1) return false;
      break;
    case Neighbourhood::k24:
      if (reach > 2) return false;
      break;
  }
  return StepValid(from, to);
}

bool GridMoves::StepValid(Cell from, Cell to) const {
  if (!Usable(from) || !Usable(to)) return false;
  if (!rules_.segment_check) return true;
  for (const Cell& c : CellsTouchedBySegment(from, to)) {
    if (!Usable(c)) return false;
  }
  const int reach = std::max(std::abs(to.x - from.x), std::abs(to.y - from.y));
  if (rules_.clearance <= 0.0 || reach <= 1) return true;
  // Longer steps with clearance: the exact distance to every blocked square nearby.
  const double res = grid_->resolution();
  const int margin = static_cast<int>(std::ceil(rules_.clearance / res)) + 1;
  const Point2 a = grid_->CellCenter(from), b = grid_->CellCenter(to);
  for (int y = std::min(from.y, to.y) - margin; y <= std::max(from.y, to.y) + margin; ++y) {
    for (int x = std::min(from.x, to.x) - margin; x <= std::max(from.x, to.x) + margin; ++x) {
      if (!grid_->InBounds(x, y) || !grid_->IsBlocked(x, y)) continue;
      const Point2 lo = grid_->origin() + Point2(x, y) * res;
      const Point2 hi = lo + Point2(res, res);
      if (SegmentBoxDistance(a, b, lo, hi) < rules_.clearance) return false;
    }
  }
  return true;
}

const std::vector<Cell>& GridMoves::ValidMoves(Cell from) {
  static const std::vector<Cell> kNone;
  if (!Usable(from)) return kNone;
  const size_t i = Index(from);
  if (!moves_known_[i]) {
    for (const Cell& d : MoveOffsets(rules_.neighbourhood)) {
      const Cell to{from.x + d.x, from.y + d.y};
      if (StepValid(from, to)) moves_[i].push_back(to);
    }
    moves_known_[i] = 1;
    ++cells_computed_;
  }
  return moves_[i];
}

}  // namespace swarmplan
