#pragma once

#include "core/map/map.h"
#include "core/map/point.h"

namespace swarmplan {

// The measures every plan reports, whatever the planner.
struct PathMetrics {
  double length = 0.0;          // world units (on terrain: x, y and z as given, see Terrain)
  double min_clearance = 0.0;   // smallest distance from the path to an obstacle (exact on
                                // terrain: the height above the ground; see the checkers)
  double max_curvature = 0.0;   // largest discrete curvature at an interior vertex (1/length)
  int turning_points = 0;       // interior vertices where the heading changes
  bool collision_free = false;  // every point keeps the requested clearance, inside the map
};

// Evaluates a path on a map for a given clearance. An empty path has collision_free = false.
PathMetrics EvaluatePath(const Map& map, const Path& path, double clearance);

// Polyline length.
double PathLength(const Path& path);

// The curvature at b of the polyline a-b-c: that of the circle through the three points,
// 2 sin(turn) / |ca|; 0 when they are collinear or a point repeats its neighbour, infinite at a
// reversal (a turn of pi).
double DiscreteCurvature(const Point3& a, const Point3& b, const Point3& c);

// The turns of a polyline: interior vertices where the heading changes, the largest discrete
// curvature among them (PathMetrics's), and the longest segment beside one of them (a polyline
// samples a curve of that curvature only where this is short against the curve's radius).
struct PathTurns {
  double max_curvature = 0.0;
  int turning_points = 0;
  double longest_turning_segment = 0.0;
};
PathTurns MeasureTurns(const Path& path);

}  // namespace swarmplan
