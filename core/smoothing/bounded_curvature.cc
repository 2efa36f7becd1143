#include "core/smoothing/bounded_curvature.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
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
// Vertex moves that make room for corners at most per tolerance, and candidate replacements
// tried at most per smoothing (over all tolerances).
constexpr int kRoomRounds = 64;
constexpr int kMaxRoomCandidates = 10000;
// Where a vertex may move to make room, in radii: along its lines and on rings around it (also
// the lengths of the straight pieces a vertex is split into).
constexpr double kSlidesInRadii[] = {0.125, 0.25, 0.5, 1.0, 2.0};
constexpr double kRingsInRadii[] = {0.25, 0.5, 1.0, 2.0};
constexpr int kRingDirections = 16;

double Cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

class CornerRounding {
 public:
  // `room_candidates`: the candidate replacements MoveOneVertexForRoom may still try, shared
  // with the smoothing's other attempts.
  CornerRounding(std::vector<Point2> points, const BoundedCurvatureOptions& options,
                 const CollisionChecker& checker, int& room_candidates)
      : pts_(std::move(points)),
        curvature_(1.0 / (kRadiusMargin * options.turning_radius)),
        smallest_curve_(kSmallestCurveInRadii * options.turning_radius),
        room_candidates_(room_candidates),
        options_(options),
        checker_(checker) {}

  // With `make_room`, vertices next to corners still short of the radius then move to where
  // their corners fall less short (MoveOneVertexForRoom).
  BoundedCurvatureResult Run(bool make_room) {
    for (int round = 0; round < kClearanceRepairRounds; ++round) {
      if (!MergeOneCrowdedPair() && !MoveOneCornerOut()) break;
    }
    for (int round = 0; make_room && round < kRoomRounds; ++round) {
      if (!MoveOneVertexForRoom()) break;
    }
    DropStraightVertices();
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
    std::vector<double> needed, segments;
    Measure(needed, segments);
    return FitCornerDistances(needed, segments);
  }

  // What each corner's curve needs, and each line's length.
  void Measure(std::vector<double>& needed, std::vector<double>& segments) const {
    needed.resize(corners());
    segments.resize(pts_.size() - 1);
    for (size_t i = 0; i < corners(); ++i) needed[i] = Needed(i);
    for (size_t j = 0; j < segments.size(); ++j) segments[j] = Segment(j);
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

  // Vertices that turn too little to need a curve go where the line past them is clear.
  void DropStraightVertices() {
    for (size_t i = 0; i < corners();) {
      if (Needed(i) < smallest_curve_ && Free(pts_[i], pts_[i + 2])) {
        pts_.erase(pts_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      } else {
        ++i;
      }
    }
  }

  // Corner i's curve at distance d from its vertex, halved until it keeps the clearance; none
  // (the corner stays sharp) when it is or becomes smaller than the smallest curve, or still
  // comes too close after kMaxShrinks halvings.
  std::optional<BezierCorner> ClearCorner(size_t i, double d) const {
    if (d < smallest_curve_) return std::nullopt;
    BezierCorner corner = MakeBezierCorner(pts_[i], pts_[i + 1], pts_[i + 2], d);
    for (int shrinks = 0; !CurveFree(corner); ++shrinks) {
      if (shrinks == kMaxShrinks || 0.5 * corner.d < smallest_curve_) return std::nullopt;
      corner = MakeBezierCorner(pts_[i], pts_[i + 1], pts_[i + 2], 0.5 * corner.d);
    }
    return corner;
  }

  // How far a curve at distance d falls short of the distance `needed`: 0 (room enough, or a
  // turn too small to need a curve) to 1 (sharp).
  double Shortfall(double needed, double d) const {
    return needed >= smallest_curve_ ? std::max(0.0, 1.0 - d / needed) : 0.0;
  }

  // The distance of each corner's clear curve from its vertex (0 where it stays sharp), for
  // the distances `fitted`.
  std::vector<double> ClearDistances(const std::vector<double>& fitted) const {
    std::vector<double> clear(corners());
    for (size_t i = 0; i < corners(); ++i) {
      const std::optional<BezierCorner> corner = ClearCorner(i, fitted[i]);
      clear[i] = corner ? corner->d : 0.0;
    }
    return clear;
  }

  // What may replace vertex pts_[v]: the vertex moved along its two lines towards its
  // neighbours or on rings around it, or split in two on either side of it along the mean of
  // its lines' headings (a straight piece through a vertex that has no room beside it).
  std::vector<std::vector<Point2>> Replacements(size_t v) const {
    const double radius = options_.turning_radius;
    const Point2 vertex = pts_[v];
    std::vector<std::vector<Point2>> out;
    for (const size_t neighbour : {v - 1, v + 1}) {
      const Point2 line = pts_[neighbour] - vertex;
      for (const double slide : kSlidesInRadii) {
        if (slide * radius < line.norm()) {
          out.push_back({vertex + slide * radius * line.normalized()});
        }
      }
    }
    static const std::vector<Point2> directions = [] {
      std::vector<Point2> unit;
      for (int k = 0; k < kRingDirections; ++k) {
        const double angle = 2.0 * M_PI * k / kRingDirections;
        unit.emplace_back(std::cos(angle), std::sin(angle));
      }
      return unit;
    }();
    for (const double ring : kRingsInRadii) {
      for (const Point2& direction : directions) {
        out.push_back({vertex + ring * radius * direction});
      }
    }
    const Point2 heading =
        (vertex - pts_[v - 1]).normalized() + (pts_[v + 1] - vertex).normalized();
    if (heading.norm() > 1e-9) {
      for (const double ring : kRingsInRadii) {
        const Point2 half = 0.5 * ring * radius * heading.normalized();
        out.push_back({vertex - half, vertex + half});
      }
    }
    return out;
  }

  // Takes a corner whose clear curve falls short of the radius and replaces the vertex of it or
  // of a neighbouring corner (Replacements), keeping the lines clear, by what lowers the corners'
  // summed shortfall the most (the shorter path among equals). Corners whose neighbourhood had
  // no such replacement before are not tried again, and the candidates tried per smoothing are
  // bounded (kMaxRoomCandidates). Returns whether it replaced one.
  bool MoveOneVertexForRoom() {
    std::vector<double> needed, segments;
    Measure(needed, segments);
    const std::vector<double> fitted = FitCornerDistances(needed, segments);
    const std::vector<double> clear = ClearDistances(fitted);
    double current = 0.0;
    for (size_t i = 0; i < corners(); ++i) current += Shortfall(needed[i], clear[i]);
    const double least_room = 1e-6 * options_.turning_radius;
    const std::vector<Point2> original = pts_;
    for (size_t i = 0; i < corners(); ++i) {
      if (Shortfall(needed[i], clear[i]) <= 0) continue;
      std::vector<double> window;
      for (size_t j = i > 0 ? i - 1 : 0; j < std::min(i + 4, pts_.size()); ++j) {
        window.insert(window.end(), {pts_[j].x(), pts_[j].y()});
      }
      if (stuck_.contains(window)) continue;
      bool found = false;
      double best = 0.0, best_added = 0.0;
      std::vector<Point2> best_pts;
      // Better: a lower summed shortfall than now and than the best so far, or the same as the
      // best so far on a shorter path.
      auto better = [&](double score, double added, double slack) {
        if (score >= current - 1e-9) return false;
        return !found || score < best - slack || (score <= best + slack && added < best_added);
      };
      for (size_t c = i > 0 ? i - 1 : 0; c <= std::min(i + 1, corners() - 1); ++c) {
        const size_t v = c + 1;
        const double before =
            (original[v] - original[v - 1]).norm() + (original[v + 1] - original[v]).norm();
        for (const std::vector<Point2>& replacement : Replacements(v)) {
          if (room_candidates_ == 0) return false;
          --room_candidates_;
          const auto at = static_cast<std::ptrdiff_t>(v);
          pts_.erase(pts_.begin() + at);
          pts_.insert(pts_.begin() + at, replacement.begin(), replacement.end());
          // Corner j of the new path was corner j (before the replacement) or j - grown (after
          // it) of the old; corners c - 1 .. c + 1 + grown changed shape, and lines c .. c +
          // 1 + grown length. The others keep their clear curve where their distance did not
          // change.
          const size_t grown = replacement.size() - 1;
          const size_t first = c > 0 ? c - 1 : 0, last = std::min(c + 1 + grown, corners() - 1);
          std::vector<double> trial_needed(needed), trial_segments(segments);
          trial_needed.insert(trial_needed.begin() + static_cast<std::ptrdiff_t>(c), grown, 0.0);
          trial_segments.insert(trial_segments.begin() + static_cast<std::ptrdiff_t>(c), grown,
                                0.0);
          for (size_t j = first; j <= last; ++j) trial_needed[j] = Needed(j);
          double added = -before;
          for (size_t j = c; j <= c + 1 + grown; ++j) {
            trial_segments[j] = Segment(j);
            added += trial_segments[j];
          }
          const std::vector<double> moved = FitCornerDistances(trial_needed, trial_segments);
          auto old_clear = [&](size_t j) -> std::optional<double> {
            if (j >= first && j <= last) return std::nullopt;
            const size_t old = j < c ? j : j - grown;
            if (moved[j] != fitted[old]) return std::nullopt;
            return clear[old];
          };
          // Without the clearance's shrinking first: a bound below the score.
          double bound = 0.0;
          for (size_t j = 0; j < corners(); ++j) {
            bound += Shortfall(trial_needed[j], old_clear(j).value_or(moved[j]));
          }
          bool free = better(bound, added, 2e-9);
          for (size_t j = c; free && j <= c + 1 + grown; ++j) {
            free = trial_segments[j] >= least_room && Free(pts_[j], pts_[j + 1]);
          }
          if (free) {
            double score = 0.0;
            for (size_t j = 0; j < corners(); ++j) {
              std::optional<double> d = old_clear(j);
              if (!d) {
                const std::optional<BezierCorner> corner = ClearCorner(j, moved[j]);
                d = corner ? corner->d : 0.0;
              }
              score += Shortfall(trial_needed[j], *d);
            }
            if (better(score, added, 1e-9)) {
              found = true;
              best = score;
              best_added = added;
              best_pts = pts_;
            }
          }
          pts_ = original;
        }
      }
      if (found) {
        pts_ = std::move(best_pts);
        return true;
      }
      stuck_.insert(std::move(window));
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
      const std::optional<BezierCorner> corner = ClearCorner(i, d[i]);
      if (needed >= smallest_curve_ && (!corner || corner->d < needed * (1.0 - 1e-9))) {
        ++result.corners_over;
      }
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
  double smallest_curve_;  // a corner whose curve would be shorter stays sharp
  // MoveOneVertexForRoom's state: the neighbourhoods (coordinates of the vertices around a
  // corner) where no replacement helped, and the candidates the smoothing may still try.
  std::set<std::vector<double>> stuck_;
  int& room_candidates_;
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
  int room_candidates = kMaxRoomCandidates;
  for (const bool make_room : {false, true}) {
    for (const double tolerance : kTolerancesInRadii) {
      const Path simplified =
          SimplifyWithin(flat, tolerance * options.turning_radius, checker, options.clearance);
      BoundedCurvatureResult attempt;
      if (simplified.size() < 3) {
        if (make_room) continue;
        attempt.path = simplified;
        attempt.corner_polygon = simplified;
        attempt.collision_free = checker.PathFree(simplified, options.clearance);
      } else {
        std::vector<Point2> points;
        for (const Point3& p : simplified) points.emplace_back(p.x(), p.y());
        attempt =
            CornerRounding(std::move(points), options, checker, room_candidates).Run(make_room);
      }
      if (attempt.collision_free && attempt.corners_over == 0) return attempt;
      if (!best || Better(attempt, *best)) best = std::move(attempt);
    }
  }
  return *std::move(best);
}

}  // namespace swarmplan
