#include "core/geometry/grid_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

constexpr double kHalfCellDiagonal = 0.70710678118654757;  // sqrt(2) / 2, rounded up
// Cell-boundary tolerance of the exact traversal (in cells): a segment this close to a blocked
// square counts as touching it, so rounding can only make the check stricter.
constexpr double kTouchEps = 1e-9;
// The most cells TraversalFree reads in a segment's box before its exact walk.
constexpr int kShortSegmentBoxCells = 9;
// Beyond this upper bound (cells) Clearance uses the distance-field bound instead of a scan.
constexpr double kExactReach = 4.0;
// Smallest step of the sphere tracing (cells); the slack of SegmentFree is half of it.
constexpr double kMinTraceStep = 1.0 / 16.0;
// Sample spacing of SegmentClearance (cells); its slack is half of it.
constexpr double kClearanceStep = 0.25;

// Lower bound of the clearance along the stretch between two samples `step` apart whose
// clearances are fa and fb (clearance is 1-Lipschitz).
double StretchBound(double fa, double fb, double step) {
  return std::min({fa, fb, 0.5 * (fa + fb - step)});
}

// Distance from p to the closed unit square with lower corner (x, y).
double PointSquareDistance(const Point2& p, int x, int y) {
  const double dx = std::max({0.0, x - p.x(), p.x() - (x + 1)});
  const double dy = std::max({0.0, y - p.y(), p.y() - (y + 1)});
  return std::hypot(dx, dy);
}

// True when the segment meets the closed unit square with lower corner (x, y) (slab clipping).
bool SegmentMeetsSquare(const Point2& a, const Point2& b, int x, int y) {
  double t0 = 0.0, t1 = 1.0;
  const Point2 d = b - a;
  const Point2 lo(x, y);
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > lo[axis] + 1) return false;
      continue;
    }
    double ta = (lo[axis] - a[axis]) / d[axis];
    double tb = (lo[axis] + 1 - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Exact distance between the segment and the closed unit square with lower corner (x, y): 0
// when they meet, otherwise attained at an end of the segment or at a corner of the square.
double SegmentSquareDistance(const Point2& a, const Point2& b, int x, int y) {
  if (SegmentMeetsSquare(a, b, x, y)) return 0.0;
  double best = std::min(PointSquareDistance(a, x, y), PointSquareDistance(b, x, y));
  for (const Point2& corner :
       {Point2(x, y), Point2(x + 1, y), Point2(x, y + 1), Point2(x + 1, y + 1)}) {
    best = std::min(best, PointSegmentDistance(corner, a, b));
  }
  return best;
}

// Pieces of a segment at most this long (cells) are scanned cell by cell, longer ones halved.
constexpr double kScanPieceLength = 2.0;

}  // namespace

GridCollisionChecker::GridCollisionChecker(const OccupancyGrid& grid)
    : grid_(grid), inv_resolution_(1.0 / grid.resolution()) {}

bool GridCollisionChecker::InMap(const Point2& u) const {
  return u.x() >= 0 && u.y() >= 0 && u.x() <= grid_.width() && u.y() <= grid_.height();
}

double GridCollisionChecker::LocalClearance(const Point2& u) const {
  if (!InMap(u)) return -kInf;
  const int cx = std::min(static_cast<int>(u.x()), grid_.width() - 1);
  const int cy = std::min(static_cast<int>(u.y()), grid_.height() - 1);
  if (grid_.IsBlocked(cx, cy)) {
    // Inside a blocked square: minus the depth in this square, and never 0, so that a point
    // in a blocked cell is never free, even for clearance 0.
    const double depth = std::min({u.x() - cx, cx + 1 - u.x(), u.y() - cy, cy + 1 - u.y()});
    return -std::max(depth, 1e-9);
  }
  const double centre_distance = grid_.DistanceToObstacle(cx, cy) * inv_resolution_;
  if (centre_distance == kInf) return kInf;
  const double offset = (u - Point2(cx + 0.5, cy + 0.5)).norm();
  // The blocked cell nearest the centre is at most this far from u.
  const double upper = centre_distance + offset;
  if (upper > kExactReach) {
    // Every blocked centre is >= centre_distance - offset from u, and a square reaches at
    // most half a diagonal beyond its centre.
    return std::max(0.0, centre_distance - offset - kHalfCellDiagonal - 1e-12);
  }
  // Squared distances in the scan, one square root at the end.
  double best_squared = upper * upper;
  bool found = false;
  const int x0 = std::max(0, static_cast<int>(std::ceil(u.x() - upper)) - 1);
  const int x1 = std::min(grid_.width() - 1, static_cast<int>(std::floor(u.x() + upper)));
  const int y0 = std::max(0, static_cast<int>(std::ceil(u.y() - upper)) - 1);
  const int y1 = std::min(grid_.height() - 1, static_cast<int>(std::floor(u.y() + upper)));
  for (int y = y0; y <= y1; ++y) {
    const double dy = std::max({0.0, y - u.y(), u.y() - (y + 1)});
    if (dy * dy >= best_squared) continue;
    for (int x = x0; x <= x1; ++x) {
      if (!grid_.IsBlocked(x, y)) continue;
      const double dx = std::max({0.0, x - u.x(), u.x() - (x + 1)});
      const double squared = dx * dx + dy * dy;
      if (squared < best_squared) {
        best_squared = squared;
        found = true;
      }
    }
  }
  return found ? std::min(upper, std::sqrt(best_squared)) : upper;
}

double GridCollisionChecker::Clearance(const Point3& p) const {
  const Point2 u = (p.head<2>() - grid_.origin()) * inv_resolution_;
  const double c = LocalClearance(u);
  return std::isfinite(c) ? c * grid_.resolution() : c;
}

double GridCollisionChecker::TraceClearance(const Point2& a, const Point2& b, double floor) const {
  const double length = (b - a).norm();
  double fa = LocalClearance(a);
  // +infinity only when no cell is blocked.
  if (length == 0.0 || fa < floor || fa == kInf) return fa;
  const Point2 dir = (b - a) / length;
  const bool stop_early = floor > -kInf;
  double result = fa;
  double sample_min = fa;
  double t = 0.0;
  while (t < length) {
    // With a floor, the stretch is safe while fa - floor lasts. Without one, a step of
    // fa - sample_min + kClearanceStep keeps every stretch bound >= sample_min - step / 2.
    const double step =
        stop_early ? std::max(kMinTraceStep, fa - floor) : fa - sample_min + kClearanceStep;
    const double t_next = std::min(length, t + step);
    const double fb = LocalClearance(t_next == length ? b : Point2(a + t_next * dir));
    result = std::min(result, StretchBound(fa, fb, t_next - t));
    if (result < floor) return result;
    sample_min = std::min(sample_min, fb);
    t = t_next;
    fa = fb;
  }
  return result;
}

// Branch and bound over pieces of the segment. For a piece with middle m and half-length h,
// every blocked square is at least (field distance at m's cell) - |m - cell centre| - half a
// diagonal - h away from the piece, and the nearest blocked centre to m's cell is at most
// (field distance) + |m - cell centre| from it: pieces whose lower bound exceeds the best upper
// bound so far are skipped, short pieces scan the cells within that bound.
double GridCollisionChecker::SquareDistance(const Point2& a, const Point2& b, double bound,
                                            bool stop_below_bound) const {
  if (grid_.BlockedCount() == 0) return kInf;
  const Point2 d = b - a;
  const double length = d.norm();
  double threshold = bound;  // the exact distance is <= threshold, or >= bound
  double found = kInf;       // the least exact distance to a scanned square
  struct Piece {
    double t0, t1;
  };
  Piece stack[64];
  int top = 0;
  stack[top++] = Piece{0.0, 1.0};
  while (top > 0) {
    const Piece piece = stack[--top];
    const Point2 p0 = a + piece.t0 * d, p1 = a + piece.t1 * d;
    const Point2 mid = 0.5 * (p0 + p1);
    const double half = 0.5 * (piece.t1 - piece.t0) * length;
    const int cx = std::clamp(static_cast<int>(std::floor(mid.x())), 0, grid_.width() - 1);
    const int cy = std::clamp(static_cast<int>(std::floor(mid.y())), 0, grid_.height() - 1);
    const double centre = grid_.DistanceToObstacle(cx, cy) * inv_resolution_;
    const double offset = (mid - Point2(cx + 0.5, cy + 0.5)).norm();
    threshold = std::min(threshold, centre + offset);
    const double lower = centre - offset - kHalfCellDiagonal - half - 1e-12;
    if (lower > threshold) continue;
    if (2 * half > kScanPieceLength && top + 2 <= 64) {
      const double t_mid = 0.5 * (piece.t0 + piece.t1);
      stack[top++] = Piece{t_mid, piece.t1};  // the nearer half (towards a) is taken first
      stack[top++] = Piece{piece.t0, t_mid};
      continue;
    }
    const Point2 lo = p0.cwiseMin(p1), hi = p0.cwiseMax(p1);
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y() - threshold)) - 1);
    const int y1 = std::min(grid_.height() - 1, static_cast<int>(std::floor(hi.y() + threshold)));
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x() - threshold)) - 1);
    const int x1 = std::min(grid_.width() - 1, static_cast<int>(std::floor(hi.x() + threshold)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (!grid_.IsBlocked(x, y)) continue;
        const double distance = SegmentSquareDistance(a, b, x, y);
        if (distance < found) {
          found = distance;
          threshold = std::min(threshold, found);
          if (stop_below_bound && found < bound) return found;
        }
      }
    }
  }
  return found < bound ? found : std::max(found, bound);
}

double GridCollisionChecker::SegmentClearance(const Point3& a, const Point3& b) const {
  const Point2 ua = (a.head<2>() - grid_.origin()) * inv_resolution_;
  const Point2 ub = (b.head<2>() - grid_.origin()) * inv_resolution_;
  if (!InMap(ua) || !InMap(ub)) return -kInf;
  const double exact = SquareDistance(ua, ub, kInf, /*stop_below_bound=*/false);
  if (exact > 0.0) return exact == kInf ? kInf : exact * grid_.resolution();
  // The segment meets a blocked square: report how deep the tracing finds it inside.
  return std::min(0.0, TraceClearance(ua, ub, -kInf)) * grid_.resolution();
}

bool GridCollisionChecker::SegmentFree(const Point3& a, const Point3& b, double clearance) const {
  const Point2 ua = (a.head<2>() - grid_.origin()) * inv_resolution_;
  const Point2 ub = (b.head<2>() - grid_.origin()) * inv_resolution_;
  if (!InMap(ua) || !InMap(ub)) return false;
  if (clearance <= 0) return TraversalFree(ua, ub);
  const double floor = clearance * inv_resolution_;
  if (TraceClearance(ua, ub, floor) >= floor) return true;
  return SquareDistance(ua, ub, floor, /*stop_below_bound=*/true) >= floor;
}

bool GridCollisionChecker::SegmentFreeByScan(const Point3& a, const Point3& b,
                                             double clearance) const {
  const Point2 ua = (a.head<2>() - grid_.origin()) * inv_resolution_;
  const Point2 ub = (b.head<2>() - grid_.origin()) * inv_resolution_;
  if (!InMap(ua) || !InMap(ub)) return false;
  if (clearance <= 0) return TraversalFree(ua, ub);
  const double floor = clearance * inv_resolution_;
  const Point2 lo = ua.cwiseMin(ub), hi = ua.cwiseMax(ub);
  const int x0 = std::max(0, static_cast<int>(std::floor(lo.x() - floor)));
  const int x1 = std::min(grid_.width() - 1, static_cast<int>(std::floor(hi.x() + floor)));
  const int y0 = std::max(0, static_cast<int>(std::floor(lo.y() - floor)));
  const int y1 = std::min(grid_.height() - 1, static_cast<int>(std::floor(hi.y() + floor)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (grid_.IsBlocked(x, y) && SegmentSquareDistance(ua, ub, x, y) < floor) return false;
    }
  }
  return true;
}

bool GridCollisionChecker::TraversalFree(const Point2& a, const Point2& b) const {
  if (!InMap(a) || !InMap(b)) return false;
  if (ShortSegmentBoxFree(a, b)) return true;
  const double y_min = std::min(a.y(), b.y());
  const double y_max = std::max(a.y(), b.y());
  const double dy = b.y() - a.y();
  const double dx = b.x() - a.x();
  const int row0 = std::max(0, static_cast<int>(std::ceil(y_min - kTouchEps)) - 1);
  const int row1 = std::min(grid_.height() - 1, static_cast<int>(std::floor(y_max + kTouchEps)));
  for (int row = row0; row <= row1; ++row) {
    // The part of the segment inside the closed band row <= y <= row + 1.
    double x_lo, x_hi;
    if (dy == 0.0) {
      x_lo = std::min(a.x(), b.x());
      x_hi = std::max(a.x(), b.x());
    } else {
      const double s0 = std::clamp((row - a.y()) / dy, 0.0, 1.0);
      const double s1 = std::clamp((row + 1 - a.y()) / dy, 0.0, 1.0);
      x_lo = a.x() + std::min(s0, s1) * dx;
      x_hi = a.x() + std::max(s0, s1) * dx;
      if (x_lo > x_hi) std::swap(x_lo, x_hi);
    }
    const int col0 = std::max(0, static_cast<int>(std::ceil(x_lo - kTouchEps)) - 1);
    const int col1 = std::min(grid_.width() - 1, static_cast<int>(std::floor(x_hi + kTouchEps)));
    for (int col = col0; col <= col1; ++col) {
      if (grid_.IsBlocked(col, row)) return false;
    }
  }
  return true;
}

bool GridCollisionChecker::ShortSegmentBoxFree(const Point2& a, const Point2& b) const {
  // The rows and columns TraversalFree reads lie within the segment's box widened by its
  // tolerance; widened by twice it, the box also covers the rounding of its band ends. Their
  // first row (column) is ceil(lower end) - 1, with ceil(t) = -floor(-t).
  const int x0 = std::max(0, -FloorToInt(-(std::min(a.x(), b.x()) - 2 * kTouchEps)) - 1);
  const int x1 = std::min(grid_.width() - 1, FloorToInt(std::max(a.x(), b.x()) + 2 * kTouchEps));
  const int y0 = std::max(0, -FloorToInt(-(std::min(a.y(), b.y()) - 2 * kTouchEps)) - 1);
  const int y1 = std::min(grid_.height() - 1, FloorToInt(std::max(a.y(), b.y()) + 2 * kTouchEps));
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > kShortSegmentBoxCells) return false;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (grid_.IsBlocked(x, y)) return false;
    }
  }
  return true;
}

}  // namespace swarmplan
