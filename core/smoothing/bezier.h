#pragma once

#include <vector>

#include "core/geometry/collision.h"
#include "core/map/map.h"
#include "core/map/point.h"

namespace swarmplan {

// Continuous-curvature cubic Bezier corners (Yang & Sukkarieh 2010, as the fish swarm paper
// uses them). At every corner W with unit vectors u1 (towards the previous point) and u2
// (towards the next), heading change γ and β = γ/2, two cubic curves replace the corner:
//   B0 = W + d·u1, B1 = B0 − g·u1, B2 = B1 − h·u1, B3 = B2 + k·u_d   (E0..E3 alike on u2,
//   E3 = E2 − k·u_d), u_d = unit(E2 − B2), h = c3·d, g = c2·c3·d, k = 6·c3·cos β·d/(c2 + 4).
// Curvature is 0 at B0 and E0, continuous across B3 = E3, and peaks there at
//   κ_max = c4·sin β / (d·cos² β).
struct BezierConstants {
  static constexpr double c1 = 7.2364;
  static const double c2;  // 2(√6 − 1)/5
  static const double c3;  // (c2 + 4)/(c1 + 6)
  static const double c4;  // (c2 + 4)²/(54·c3)
};

// Corners whose curve would end closer than this (in radii) to their vertex stay sharp: a curve
// that small would only sample the rounding of its coordinates. Such a corner turns by less
// than about a thousandth of a radian, or its lines leave it no room.
inline constexpr double kSmallestCurveInRadii = 1e-3;

// The eight control points of one corner.
struct BezierCorner {
  Point2 b[4];  // first curve, from the incoming line to the joint
  Point2 e[4];  // second curve, from the outgoing line to the joint (e[3] is the joint)
  double d = 0.0;
  double beta = 0.0;           // half the heading change
  double max_curvature = 0.0;  // κ_max of this corner
};

// Half the heading change at a corner, u1 the unit vector back along the incoming line and u2
// the one along the outgoing line.
double HalfHeadingChange(const Point2& u1, const Point2& u2);
// The corner at W with neighbours prev and next, at distance d along both lines.
BezierCorner MakeBezierCorner(const Point2& prev, const Point2& w, const Point2& next, double d);
// κ_max for a corner of half heading change β at distance d.
double BezierCornerCurvature(double beta, double d);
// The d that gives curvature κ at a corner of half heading change β.
double BezierDistanceForCurvature(double beta, double curvature);
// The corner's two curves as one polyline, `samples` chords per curve, from B0 to E0.
Path CornerPolyline(const BezierCorner& c, int samples);
// A point of the cubic Bezier with control points p[0..3], s in [0, 1].
Point2 CubicBezierPoint(const Point2 p[4], double s);
// Signed curvature of that cubic at s.
double CubicBezierCurvature(const Point2 p[4], double s);

// The distance d of each corner's curves from its vertex: `wanted` (corner i at the joint of
// segments i and i + 1), bounded by both segments and shared between neighbouring corners so
// that their curves never overlap (d_i + d_(i+1) <= segment i + 1).
std::vector<double> FitCornerDistances(const std::vector<double>& wanted,
                                       const std::vector<double>& segments);
// The same in place: d[0..corners) holds the wanted distances, segments[0..corners] the lines.
void FitCornerDistances(double* d, const double* segments, size_t corners);

struct BezierOptions {
  double min_turning_radius = 1.0;  // world units; d is chosen so κ_max = 1 / radius
  int samples_per_curve = 16;       // points per cubic in the output polyline
  double clearance = 0.0;
  int max_shrinks = 8;  // a colliding corner's d is halved at most this often, then left sharp
};

// The options `Smooth(..., "bezier", ...)` uses (ours): a minimum turning radius of one cell on
// grids and 1/100 of the larger side of a shape world, 16 samples per curve.
BezierOptions DefaultBezierOptions(const Map& map, double clearance);

struct BezierResult {
  Path path;                   // the smoothed polyline (z = 0)
  double max_curvature = 0.0;  // the largest κ_max over the smoothed corners (1/world units)
  int corners = 0;             // corners after collinear pruning
  int corners_limited = 0;     // corners whose d was bounded by the segments (κ above 1/radius)
  int corners_shrunk = 0;      // corners whose d was shrunk to avoid a collision
  int corners_sharp = 0;       // corners left as they were (no collision-free curve found)
  bool collision_free = true;  // according to the checker, when one was given
};

// Smooths a 2D polyline: collinear points are pruned first, then every corner gets a Bezier pair
// with d from the minimum turning radius, bounded so that neighbouring corners never overlap
// (d_i + d_(i+1) ≤ the segment between them, d ≤ the first and last segment). With a checker,
// each corner whose curves come closer than the clearance to an obstacle has its d halved until
// they do not (at most max_shrinks times, then the corner stays sharp).
BezierResult SmoothWithBezier(const Path& raw, const BezierOptions& options,
                              const CollisionChecker* checker);

}  // namespace swarmplan
