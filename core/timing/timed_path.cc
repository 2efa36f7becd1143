#include "core/timing/timed_path.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "core/path_metrics.h"

namespace swarmplan {

absl::Status ValidateVehicleLimits(const VehicleLimits& vehicle) {
  const struct {
    const char* name;
    double value;
  } fields[] = {{"max_speed", vehicle.max_speed},
                {"max_acceleration", vehicle.max_acceleration},
                {"max_yaw_rate", vehicle.max_yaw_rate}};
  for (const auto& field : fields) {
    if (!std::isfinite(field.value) || field.value < 0) {
      return absl::InvalidArgumentError(
          absl::StrCat("vehicle.", field.name, ": must be finite and >= 0, got ", field.value));
    }
  }
  if (vehicle.timed() && vehicle.max_acceleration == 0.0) {
    return absl::InvalidArgumentError(
        "vehicle.max_acceleration: must be > 0 when vehicle.max_speed is set");
  }
  return absl::OkStatus();
}

namespace {

// The fastest time over a segment of length s from speed v0 to v1 (|v1^2 - v0^2| <= 2 a s):
// accelerate at a to the peak speed, cruise at it, brake at a.
double SegmentTime(double s, double v0, double v1, const VehicleLimits& vehicle) {
  if (s <= 0.0) return 0.0;
  const double a = vehicle.max_acceleration;
  const double peak = std::min(vehicle.max_speed, std::sqrt(a * s + 0.5 * (v0 * v0 + v1 * v1)));
  const double rising = (peak * peak - v0 * v0) / (2.0 * a);
  const double falling = (peak * peak - v1 * v1) / (2.0 * a);
  const double cruising = std::max(0.0, s - rising - falling);
  return (peak - v0) / a + (peak - v1) / a + cruising / peak;
}

}  // namespace

TimedPath TimePath(const Path& path, const VehicleLimits& vehicle) {
  TimedPath timed;
  const size_t n = path.size();
  if (n == 0) return timed;
  std::vector<double> segment(n > 1 ? n - 1 : 0);
  for (size_t i = 0; i + 1 < n; ++i) segment[i] = (path[i + 1] - path[i]).norm();

  // The speed each point allows on its own: at rest at the ends, the curvature's bounds inside.
  std::vector<double> speed(n, vehicle.max_speed);
  speed.front() = 0.0;
  speed.back() = 0.0;
  for (size_t i = 1; i + 1 < n; ++i) {
    const double kappa = DiscreteCurvature(path[i - 1], path[i], path[i + 1]);
    if (kappa <= 0.0) continue;
    if (std::isinf(kappa)) {
      speed[i] = 0.0;
      continue;
    }
    speed[i] = std::min(speed[i], std::sqrt(vehicle.max_acceleration / kappa));
    if (vehicle.max_yaw_rate > 0.0) speed[i] = std::min(speed[i], vehicle.max_yaw_rate / kappa);
  }
  // Reachable accelerating forward from the start, and braking backward to the goal.
  const double a = vehicle.max_acceleration;
  for (size_t i = 0; i + 1 < n; ++i) {
    speed[i + 1] = std::min(speed[i + 1], std::sqrt(speed[i] * speed[i] + 2.0 * a * segment[i]));
  }
  for (size_t i = n - 1; i > 0; --i) {
    speed[i - 1] =
        std::min(speed[i - 1], std::sqrt(speed[i] * speed[i] + 2.0 * a * segment[i - 1]));
  }

  timed.points.resize(n);
  double time = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (i > 0) time += SegmentTime(segment[i - 1], speed[i - 1], speed[i], vehicle);
    timed.points[i] = {path[i], time, speed[i]};
  }
  timed.duration = time;
  return timed;
}

}  // namespace swarmplan
