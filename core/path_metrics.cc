#include "core/path_metrics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/geometry/collision.h"

namespace swarmplan {
namespace {

// Heading changes up to this (radians) are not turning points.
constexpr double kTurnThreshold = 1e-6;

// The path without repeated consecutive points, which have no heading.
Path WithoutRepeats(const Path& path) {
  Path out;
  out.reserve(path.size());
  for (const Point3& p : path) {
    if (out.empty() || p != out.back()) out.push_back(p);
  }
  return out;
}

struct Turn {
  double sine = 0.0;  // |u x w| / (|u| |w|), u = b - a, w = c - b
  double angle = 0.0;
};

// The turn at b of a-b-c; none when a point repeats its neighbour.
Turn TurnAt(const Point3& a, const Point3& b, const Point3& c) {
  const Point3 u = b - a;
  const Point3 w = c - b;
  const double norms = u.norm() * w.norm();
  if (norms == 0.0) return {};
  const double cross = u.cross(w).norm();
  return {cross / norms, std::atan2(cross, u.dot(w))};
}

}  // namespace

double PathLength(const Path& path) {
  double length = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) length += (path[i + 1] - path[i]).norm();
  return length;
}

double DiscreteCurvature(const Point3& a, const Point3& b, const Point3& c) {
  const Turn turn = TurnAt(a, b, c);
  if (turn.angle == 0.0) return 0.0;
  const double chord = (c - a).norm();
  if (turn.angle >= std::numbers::pi || chord == 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  return 2.0 * turn.sine / chord;
}

PathTurns MeasureTurns(const Path& path) {
  PathTurns turns;
  const Path v = WithoutRepeats(path);
  for (size_t i = 1; i + 1 < v.size(); ++i) {
    if (TurnAt(v[i - 1], v[i], v[i + 1]).angle <= kTurnThreshold) continue;
    ++turns.turning_points;
    turns.longest_turning_segment = std::max(
        {turns.longest_turning_segment, (v[i] - v[i - 1]).norm(), (v[i + 1] - v[i]).norm()});
    turns.max_curvature =
        std::max(turns.max_curvature, DiscreteCurvature(v[i - 1], v[i], v[i + 1]));
  }
  return turns;
}

PathMetrics EvaluatePath(const Map& map, const Path& path, double clearance) {
  PathMetrics m;
  m.length = PathLength(path);
  if (path.empty()) {
    m.min_clearance = -std::numeric_limits<double>::infinity();
    return m;
  }
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(map);
  m.min_clearance = checker->PathClearance(path);
  m.collision_free = checker->PathFree(path, clearance);
  const PathTurns turns = MeasureTurns(path);
  m.max_curvature = turns.max_curvature;
  m.turning_points = turns.turning_points;
  return m;
}

}  // namespace swarmplan
