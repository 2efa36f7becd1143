#include "core/smoothing/smoothing.h"

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "core/geometry/collision.h"

namespace swarmplan {

std::vector<std::string> SmoothingMethods() { return {"none"}; }

absl::StatusOr<SmoothingResult> Smooth(const std::string& method, const Map& map, const Path& raw,
                                       double clearance) {
  SmoothingResult result;
  if (method == "none" || method.empty()) {
    result.path = raw;
  } else {
    return absl::InvalidArgumentError(absl::StrCat("smoothing: unknown method '", method,
                                                   "'; available: ",
                                                   absl::StrJoin(SmoothingMethods(), ", ")));
  }
  result.collision_free = MakeCollisionChecker(map)->PathFree(result.path, clearance);
  return result;
}

}  // namespace swarmplan
