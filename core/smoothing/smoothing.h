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
};

// The smoothing methods a request may name ("none" always among them).
std::vector<std::string> SmoothingMethods();

// Smooths a raw path. INVALID_ARGUMENT for an unknown method. The result is checked for
// collisions with `clearance` and says whether smoothing kept the path collision-free.
absl::StatusOr<SmoothingResult> Smooth(const std::string& method, const Map& map, const Path& raw,
                                       double clearance);

}  // namespace swarmplan
