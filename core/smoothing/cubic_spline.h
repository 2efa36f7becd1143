#pragma once

#include <vector>

#include "core/map/point.h"

namespace swarmplan {

// End conditions of a cubic spline: not-a-knot (third derivative continuous at the second and
// the second-to-last knot, like MATLAB's `spline`) or natural (zero second derivative).
enum class SplineEnd { kNotAKnot, kNatural };

// A parametric cubic spline through a list of points, with the uniform parameter s = 0, 1, ...,
// n-1 at the knots; each coordinate is splined separately. Two knots give the straight segment;
// three knots with not-a-knot ends give the parabola through them. Fitting and sampling reuse
// the spline's buffers, so a spline kept across calls does not allocate once warmed up.
class CubicSpline {
 public:
  // Fits the spline; `knots` must hold at least two points.
  void Fit(const std::vector<Point3>& knots, SplineEnd end);

  // The point at parameter s in [0, n-1] (clamped).
  Point3 Evaluate(double s) const;

  // `count` (>= 2) points at uniform parameter steps, the first and last knots included.
  void SampleByCount(int count, std::vector<Point3>& out) const;
  // Points along every piece at a spacing of at most about `spacing` (> 0) along the curve;
  // every knot is included.
  void SampleBySpacing(double spacing, std::vector<Point3>& out) const;

  int knot_count() const { return static_cast<int>(knots_.size()); }

 private:
  std::vector<Point3> knots_;
  std::vector<Point3> second_;  // second derivatives at the knots (per coordinate)
  std::vector<double> diag_, rhs_scratch_;
  std::vector<Point3> rhs_;
};

// Convenience: fit and sample by count in one call (allocates; not for hot loops).
std::vector<Point3> SplineThrough(const std::vector<Point3>& knots, int count,
                                  SplineEnd end = SplineEnd::kNotAKnot);

}  // namespace swarmplan
