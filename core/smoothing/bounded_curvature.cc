#include "core/smoothing/bounded_curvature.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/path_metrics.h"
#include "core/smoothing/bezier.h"
#include "core/smoothing/simplify.h"

namespace swarmplan {
namespace {

constexpr double kRadiusMargin = 1.01;
// A polyline whose segments beside every turn are at most this many radii long samples a curve;
// longer ones meet at corners, however small their discrete curvature.
constexpr double kSampledCurveSegmentInRadii = 0.25;
constexpr double kTolerancesInRadii[] = {0.05, 0.1, 0.2, 0.4, 0.8, 1.6};
// Merges and outward moves per tolerance at most.
constexpr int kClearanceRepairRounds = 32;
// Halvings of a colliding corner's curve before it stays sharp.
constexpr int kMaxShrinks = 8;

double Cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

class CornerRounding {
 public:
  CornerRounding(std::vector<Point2> points, const BoundedCurvatureOptions& options,
                 const CollisionChecker& checker)
      : pts_(std::move(points)),
        curvature_(1.0 / (kRadiusMargin * options.turning_radius)),
        options_(options),
        checker_(checker) {}

  BoundedCurvatureResult Run() {
    for (int round = 0; round < kClearanceRepairRounds; ++round) {
      if (!MergeOneCrowdedPair() && !MoveOneCornerOut()) break;
    }
    return Assemble();
  }

 private:
  size_t corners() const { return pts_.size() - 2; }  // corner i sits at pts_[i + 1]

  Point2 Back(size_t i) const { return (pts_[i] - pts_[i + 1]).normalized(); }
  Point2 Ahead(size_t i) const { return (pts_[i + 2] - pts_[i + 1]).normalized(); }
  double Needed(size_t i) const {
    return BezierDistanceForCurvature(HalfHeadingChange(Back(i), Ahead(i)), curvature_);
  }
  double TurnSign(size_t i) const {
    return Cross(pts_[i + 1] - pts_[i], pts_[i + 2] - pts_[i + 1]) >= 0 ? 1.0 : -1.0;
  }
  bool Free(const Point2& a, const Point2& b) const {
    return checker_.SegmentFree(Lift(a), Lift(b), options_.clearance);
  }
  double Segment(size_t j) const { return (pts_[j + 1] - pts_[j]).norm(); }

  // The distance of each corner's curve from its vertex: what the curvature needs, within the
  // room the segments leave.
  std::vector<double> Fit() const {
    std::vector<double> needed(corners()), segments(pts_.size() - 1);
    for (size_t i = 0; i < corners(); ++i) needed[i] = Needed(i);
    for (size_t j = 0; j < segments.size(); ++j) segments[j] = Segment(j);
    return FitCornerDistances(needed, segments);
  }

  // Corners i and i + 1 turning the same way with too little room between them become one at
  // the meeting point of the line into i and the line out of i + 1.
  bool MergeOneCrowdedPair() {
    for (size_t i = 0; i + 1 < corners(); ++i) {
      if (Needed(i) + Needed(i + 1) <= Segment(i + 1)) continue;
      if (TurnSign(i) != TurnSign(i + 1)) continue;
      const Point2 a = pts_[i], r = pts_[i + 1] - pts_[i];
      const Point2 b = pts_[i + 3], s = pts_[i + 2] - pts_[i + 3];
      const double denominator = Cross(r, s);
      if (std::abs(denominator) < 1e-12 * r.norm() * s.norm()) continue;
      const double t = Cross(b - a, s) / denominator;
      const double u = Cross(b - a, r) / denominator;
      if (t <= 1.0 || u <= 1.0) continue;
      const Point2 meet = a + t * r;
      if (!Free(a, meet) || !Free(meet, b)) continue;
      pts_[i + 1] = meet;
      pts_.erase(pts_.begin() + static_cast<std::ptrdiff_t>(i) + 2);
      return true;
    }
    return false;
  }

  bool CurveFree(const BezierCorner& corner) const {
    return checker_.PathFree(CornerPolyline(corner, options_.samples_per_curve),
                             options_.clearance);
  }

  // The first corner whose curve comes too close to an obstacle moves outward along its
  // bisector by the depth of its curve (or half of it), when its lines stay clear.
  bool MoveOneCornerOut() {
    const std::vector<double> d = Fit();
    for (size_t i = 0; i < corners(); ++i) {
      const BezierCorner corner = MakeBezierCorner(pts_[i], pts_[i + 1], pts_[i + 2], d[i]);
      if (CurveFree(corner)) continue;
      const Point2 inward = Back(i) + Ahead(i);
      if (inward.norm() < 1e-9) continue;
      const double depth = (corner.b[3] - pts_[i + 1]).norm();
      for (const double fraction : {1.0, 0.5}) {
        const Point2 moved = pts_[i + 1] - fraction * depth * inward.normalized();
        if (depth <= 0 || !Free(pts_[i], moved) || !Free(moved, pts_[i + 2])) continue;
        pts_[i + 1] = moved;
        return true;
      }
    }
    return false;
  }

  BoundedCurvatureResult Assemble() const {
    BoundedCurvatureResult result;
    result.corners = static_cast<int>(corners());
    for (const Point2& p : pts_) result.corner_polygon.push_back(Lift(p));
    const std::vector<double> d = Fit();
    Path& out = result.path;
    out.push_back(Lift(pts_.front()));
    for (size_t i = 0; i < corners(); ++i) {
      const double needed = Needed(i);
      std::optional<BezierCorner> corner =
          MakeBezierCorner(pts_[i], pts_[i + 1], pts_[i + 2], d[i]);
      for (int shrinks = 0; !CurveFree(*corner); ++shrinks) {
        if (shrinks == kMaxShrinks) {
          corner.reset();
          break;
        }
        *corner = MakeBezierCorner(pts_[i], pts_[i + 1], pts_[i + 2], 0.5 * corner->d);
      }
      if (!corner || corner->d < needed * (1.0 - 1e-9)) ++result.corners_over;
      if (!corner) {
        out.push_back(Lift(pts_[i + 1]));
        continue;
      }
      result.max_curvature = std::max(result.max_curvature, corner->max_curvature);
      for (const Point3& q : CornerPolyline(*corner, options_.samples_per_curve)) {
        if ((out.back() - q).norm() >= 1e-12) out.push_back(q);
      }
    }
    if ((out.back() - Lift(pts_.back())).norm() >= 1e-12) out.push_back(Lift(pts_.back()));
    result.collision_free = checker_.PathFree(out, options_.clearance);
    return result;
  }

  std::vector<Point2> pts_;
  double curvature_;
  const BoundedCurvatureOptions& options_;
  const CollisionChecker& checker_;
};

// Clear first, then fewer corners over the curvature.
bool Better(const BoundedCurvatureResult& a, const BoundedCurvatureResult& b) {
  if (a.collision_free != b.collision_free) return a.collision_free;
  return a.corners_over < b.corners_over;
}

}  // namespace

BoundedCurvatureResult SmoothToTurningRadius(const Path& raw,
                                             const BoundedCurvatureOptions& options,
                                             const CollisionChecker& checker) {
  Path flat;
  flat.reserve(raw.size());
  for (const Point3& p : raw) flat.emplace_back(p.x(), p.y(), 0.0);
  // A path that already samples a curve turning no tighter than the radius (short segments at
  // every turn) and keeps the clearance stays as it is.
  const PathTurns turns = MeasureTurns(flat);
  if (turns.max_curvature <= 1.0 / options.turning_radius &&
      turns.longest_turning_segment <= kSampledCurveSegmentInRadii * options.turning_radius &&
      checker.PathFree(flat, options.clearance)) {
    BoundedCurvatureResult kept;
    kept.path = std::move(flat);
    kept.max_curvature = turns.max_curvature;
    kept.collision_free = true;
    kept.corner_polygon = kept.path;
    return kept;
  }
  std::optional<BoundedCurvatureResult> best;
  for (const double tolerance : kTolerancesInRadii) {
    const Path simplified =
        SimplifyWithin(flat, tolerance * options.turning_radius, checker, options.clearance);
    BoundedCurvatureResult attempt;
    if (simplified.size() < 3) {
      attempt.path = simplified;
      attempt.corner_polygon = simplified;
      attempt.collision_free = checker.PathFree(simplified, options.clearance);
    } else {
      std::vector<Point2> points;
      for (const Point3& p : simplified) points.emplace_back(p.x(), p.y());
      attempt = CornerRounding(std::move(points), options, checker).Run();
    }
    if (attempt.collision_free && attempt.corners_over == 0) return attempt;
    if (!best || Better(attempt, *best)) best = std::move(attempt);
  }
  return *std::move(best);
}

}  // namespace swarmplan
