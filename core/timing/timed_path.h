#pragma once

#include <vector>

#include "absl/status/status.h"
#include "core/map/point.h"

namespace swarmplan {

// What a vehicle can do, in map units and seconds. With max_speed > 0 a plan is timed.
struct VehicleLimits {
  double max_speed = 0.0;         // units / s; 0: the plan is not timed
  double max_acceleration = 0.0;  // units / s^2, along the path and across it (v^2 kappa)
  double max_yaw_rate = 0.0;      // rad / s; 0: no limit
  bool timed() const { return max_speed > 0.0; }
};

// INVALID_ARGUMENT naming the field ("vehicle.max_speed", ...) when a value is negative or not
// finite, or when max_speed is set without a max_acceleration.
absl::Status ValidateVehicleLimits(const VehicleLimits& vehicle);

struct TimedPoint {
  Point3 point = Point3::Zero();
  double time = 0.0;   // seconds from the start
  double speed = 0.0;  // units / s
};

struct TimedPath {
  std::vector<TimedPoint> points;  // one per point of the path, in order
  double duration = 0.0;           // seconds; the last point's time
};

// The fastest timing of `path` within the limits, starting and ending at rest. At each interior
// vertex the speed keeps v^2 kappa <= max_acceleration and, with a yaw-rate limit,
// v kappa <= max_yaw_rate, kappa the discrete curvature there (DiscreteCurvature, as
// PathMetrics measures it: a sampled curve's, or at a polyline's corner that of the circle
// through it and its neighbours); along a segment the speed rises at max_acceleration up to at
// most max_speed and falls at it to the next point's. A reversal (kappa infinite) is passed at
// rest. `vehicle` must be timed() and valid.
TimedPath TimePath(const Path& path, const VehicleLimits& vehicle);

}  // namespace swarmplan
