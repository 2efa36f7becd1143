#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/map.h"

namespace swarmplan {

struct SmoothingResult {
  Path path;
  bool collision_free = true;  // the smoothed path keeps the clearance
  // "bounded-curvature": every corner got a curve within 1 / turning radius (none had to turn
  // tighter for lack of room or clearance); true for the other methods.
  bool within_turning_radius = true;
};

// The smoothing methods a request may name ("none" always among them).
std::vector<std::string> SmoothingMethods();

// Smooths a raw path. INVALID_ARGUMENT for an unknown method. The result is checked for
// collisions with `clearance` and says whether smoothing kept the path collision-free.
// "bounded-curvature" (SmoothToTurningRadius) keeps the curvature within 1 / `turning_radius`,
// or, with a turning radius of 0, within the one "bezier" uses (DefaultBezierOptions).
absl::StatusOr<SmoothingResult> Smooth(const std::string& method, const Map& map, const Path& raw,
                                       double clearance, double turning_radius = 0.0);

}  // namespace swarmplan
