#pragma once

#include "core/geometry/collision.h"
#include "core/map/point.h"

namespace swarmplan {

struct BoundedCurvatureOptions {
  double turning_radius = 1.0;  // world units: no curve turns tighter than this
  double clearance = 0.0;       // every point of the result keeps it
  int samples_per_curve = 16;   // chords per cubic in the output polyline
};

struct BoundedCurvatureResult {
  Path path;                   // the smoothed polyline (z = 0)
  double max_curvature = 0.0;  // the largest analytic curvature of the corners' curves (of a
                               // path kept as it is, its discrete curvature)
  int corners = 0;             // corners of the simplified path that got a curve
  int corners_over = 0;        // corners that had no room or clearance for 1 / radius
  bool collision_free = false;
  // The straight lines whose corners were rounded (the path itself when it was kept): rounded
  // again to the same radius (RoundedCornerPath), they give `path` where no curve was shrunk.
  Path corner_polygon;
};

// Smooths a 2D path into straight lines joined by continuous-curvature Bezier corners (bezier.h)
// whose curvature peaks at 1 / turning radius, keeping the clearance. A path that keeps the
// clearance, samples a curve (no segment beside a turn longer than a quarter radius) and whose
// discrete curvature (MeasureTurns) is already within 1 / radius is returned as it is
// (flattened to z = 0). Otherwise:
// 1. SimplifyWithin the path at a tolerance of 0.05 turning radii (then 0.1, 0.2, ... 1.6 when
//    the corners do not fit), so a densely sampled path becomes its few real corners;
// 2. neighbouring corners that turn the same way and need more room than the segment between
//    them become one corner where their outer lines meet;
// 3. a corner whose curve comes closer than the clearance to an obstacle moves outward along
//    its bisector (its curve moves with it), when its two lines stay clear;
// 4. a corner still without room or clearance gets a shorter curve, turning tighter than
//    1 / radius (counted in corners_over), or stays sharp.
// The first tolerance with every corner at 1 / radius and the whole path clear is the result.
// When no tolerance gives one, the tolerances are tried again with a step between 3 and 4: while
// a corner falls short, the vertex of it or of a neighbour moves (along its lines, or up to two
// radii in any direction) or splits in two about a straight piece through it, keeping its lines
// clear, wherever that lowers the corners' summed shortfall of the distance their curves need
// the most; so an S-bend whose middle line is too short, or a turn just before a gap as wide as
// the clearance allows, finds room beside it when the map has any (at most 10000 candidate
// moves per smoothing, which bounds the time a path without room anywhere takes). Failing that
// too, the result is the clear attempt with the fewest corners over. The corners are designed
// for a radius 1 % larger, so the sampled polyline's discrete curvature stays within 1 / radius.
BoundedCurvatureResult SmoothToTurningRadius(const Path& raw,
                                             const BoundedCurvatureOptions& options,
                                             const CollisionChecker& checker);

}  // namespace swarmplan
