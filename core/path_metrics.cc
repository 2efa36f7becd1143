#include "core/path_metrics.h"

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

}  // namespace

double PathLength(const Path& path) {
  double length = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) length += (path[i + 1] - path[i]).norm();
  return length;
}

// Curvature at an interior vertex b between a and c is that of the circle through a, b and
// c: 4 * area / (|ab| |bc| |ca|) = 2 sin(turn) / |ca|. A reversal (turn of pi) has infinite
// curvature.
PathTurns MeasureTurns(const Path& path) {
  PathTurns turns;
  const Path v = WithoutRepeats(path);
  for (size_t i = 1; i + 1 < v.size(); ++i) {
    const Point3 u = v[i] - v[i - 1];
    const Point3 w = v[i + 1] - v[i];
    const double sine =  // |u x w|
        Point3(u.y() * w.z() - u.z() * w.y(), u.z() * w.x() - u.x() * w.z(),
               u.x() * w.y() - u.y() * w.x())
            .norm();
    const double turn = std::atan2(sine, u.dot(w));
    if (turn <= kTurnThreshold) continue;
    ++turns.turning_points;
    turns.longest_turning_segment = std::max({turns.longest_turning_segment, u.norm(), w.norm()});
    const double chord = (v[i + 1] - v[i - 1]).norm();
    const double curvature = (turn >= std::numbers::pi || chord == 0.0)
                                 ? std::numeric_limits<double>::infinity()
                                 : 2.0 * sine / (u.norm() * w.norm()) / chord;
    turns.max_curvature = std::max(turns.max_curvature, curvature);
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
