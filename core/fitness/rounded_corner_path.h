#pragma once

#include <vector>

namespace swarmplan {

// The path through knots K_0..K_(n-1) as straight lines whose interior corners are rounded by
// continuous-curvature Bezier pairs (core/smoothing/bezier.h, the corners of the bounded-curvature
// smoothing): every corner whose lines leave room turns no tighter than 1 / turning radius; the
// room of a line is shared between its two corners (FitCornerDistances), so a corner with too
// little turns tighter, which the fleet objective's curvature term prices. Straight parts are
// sampled at most `spacing` apart, and at most a fifth of a radius beside each corner; each cubic
// with 16, 32, 48 or 64 chords, of at most a fifth of a radius where 64 suffice (16 as the
// smoothing samples its curves, whose points are then among these). With the knots a seed's
// vertices and every offset 0, the path is the seed after the smoothing's corner rounding.
class RoundedCornerPath {
 public:
  // At most `max_points` points per path: when the straight parts would need more, their
  // spacing grows.
  RoundedCornerPath(int knots, double turning_radius, double spacing, int max_points);

  int knots() const { return knots_; }
  int max_points() const { return max_points_; }

  // Writes the path's points for the knots (kx[j], ky[j]), j < knots(), and returns their count
  // (<= max_points()). `scratch` holds at least 2 * knots() doubles.
  int Apply(const double* kx, const double* ky, double* px, double* py, double* scratch) const;
  // How far from each knot its curve begins and ends along its lines (0 at the ends and at
  // corners that stay sharp) into distance[0..knots()), the lines' lengths into
  // segment[0..knots() - 1); returns their sum.
  double CornerDistances(const double* kx, const double* ky, double* segment,
                         double* distance) const;

 private:
  int knots_;
  double curvature_;       // what each corner is designed for: 1 / (1.01 radius)
  double near_curve_;      // the longest straight piece beside a curve, and the longest chord
  double smallest_curve_;  // a corner whose curve would be shorter stays sharp
  double spacing_;         // the longest straight piece elsewhere
  int max_points_;
};

}  // namespace swarmplan
