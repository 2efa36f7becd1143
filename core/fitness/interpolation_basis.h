#pragma once

#include <memory>
#include <vector>

#include "core/operators/waypoint_path.h"

namespace swarmplan {

// The path start -> k waypoints -> goal of WaypointPathBuilder as local linear combinations of
// its k + 2 knots K: every path point lies on one piece (K_j, K_j+1) and is
//   p = a K_j + b K_j+1 + c M_j + d M_j+1,
// M the second derivatives of the not-a-knot spline at the knots (spline only; c = d = 0
// otherwise). The spline's parameter at each knot is fixed (uniform, as WaypointPathBuilder's,
// or given: e.g. the knots' arc length along a seed path, which keeps the spline from
// overshooting between unevenly spaced knots), so the weights are fixed per point, and M is one
// tridiagonal solve whose factors are fixed too: a path costs O(k + points), whatever k. Points
// lie at equal parameter steps. The staircase has other weights for x than for y. Immutable once
// built; share it (Cached).
class InterpolationBasis {
 public:
  // WaypointPathBuilder's path: the knots at parameters 0, 1, ..., waypoints + 1.
  InterpolationBasis(Interpolation interpolation, int waypoints, int samples);
  // The knots at the given increasing parameters (at least three); kPolyline gives each piece
  // its share of the samples by parameter length.
  InterpolationBasis(Interpolation interpolation, const std::vector<double>& parameters,
                     int samples);

  int points() const { return static_cast<int>(ax_.size()); }
  int knots() const { return knots_; }
  bool uses_moments() const { return spline_; }
  // Memory held, for the cache's bound.
  size_t MemoryBytes() const;

  // Writes the path's points for the knots (kx[j], ky[j]), j < knots(). `moments` is scratch
  // of at least 2 * knots() doubles.
  void Apply(const double* kx, const double* ky, double* px, double* py, double* moments) const;

 private:
  InterpolationBasis(Interpolation interpolation, const std::vector<double>& parameters,
                     int samples, bool uniform);
  // The Thomas factors of the spline's moment system for the parameter steps h.
  void FactorMomentSystem(const std::vector<double>& h);
  // The spline's second derivatives m[0..n) of one coordinate's knots v[0..n).
  void Moments(const double* v, double* m) const;
  // Adds one coordinate's points for the knots v and moments m (m unused without moments).
  void ApplyCoordinate(const double* v, const double* m, const std::vector<double>& a,
                       const std::vector<double>& b, double* p) const;

  int knots_ = 0;
  bool spline_ = false;
  // Points [first_[j], first_[j + 1]) lie on piece j.
  std::vector<int> first_;
  std::vector<double> ax_, bx_, ay_, by_, c_, d_;
  // The Thomas sweep of the moment system, per unknown: the factor of the previous row, the
  // pivot's inverse, and the modified super-diagonal.
  std::vector<double> sub_, pivot_, super_;
  std::vector<double> h_, inverse_h_;  // the parameter steps between the knots
};

// The basis for (interpolation, waypoints, samples), built once per process and shared
// (thread-safe). Bases beyond kMaxCachedBasisBytes in all are built for the caller alone, so
// hostile sizes cannot fill the cache.
std::shared_ptr<const InterpolationBasis> CachedInterpolationBasis(Interpolation interpolation,
                                                                   int waypoints, int samples);

inline constexpr size_t kMaxCachedBasisBytes = size_t{64} << 20;

}  // namespace swarmplan
