#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/point.h"
#include "core/smoothing/cubic_spline.h"

namespace swarmplan {

// How the waypoints of a 2D path are joined (AEM-BSO Table 2): a parametric not-a-knot cubic
// spline sampled at `samples` points; straight segments; or nearest-neighbour interpolation of y
// over x, which makes a staircase (x moves linearly, y jumps half-way between waypoints).
// kPolyline is kLinear with each segment sampled evenly, (samples - 1) / (k + 1) points a
// segment, for objectives read at the path's points (the fleet objective of seeded planners);
// it is not a parameter value.
enum class Interpolation { kSpline, kLinear, kNearest, kPolyline };

absl::StatusOr<Interpolation> ParseInterpolation(const std::string& name);
std::vector<std::string> InterpolationNames();

// Builds the path start -> waypoints -> goal from a decision vector [x1..xk, y1..yk]
// (AEM-BSO eq 20). Reuses its buffers: no allocation per call once warmed up.
class WaypointPathBuilder {
 public:
  WaypointPathBuilder(const Point3& start, const Point3& goal, int waypoints,
                      Interpolation interpolation, int samples);

  int waypoints() const { return waypoints_; }
  // The path for `x`; the reference stays valid until the next call.
  const Path& Build(const Eigen::VectorXd& x);
  // The knots start, waypoints, goal for `x`.
  void Knots(const Eigen::VectorXd& x, std::vector<Point3>& knots) const;

 private:
  Point3 start_, goal_;
  int waypoints_;
  Interpolation interpolation_;
  int samples_;
  std::vector<Point3> knots_;
  CubicSpline spline_;
  Path path_;
};

}  // namespace swarmplan
