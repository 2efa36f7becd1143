#include "core/smoothing/smoothing.h"

#include <algorithm>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "core/geometry/collision.h"
#include "core/smoothing/bezier.h"
#include "core/smoothing/bounded_curvature.h"
#include "core/smoothing/cubic_spline.h"

namespace swarmplan {

namespace {

// The spacing of cubic-spline samples: half a cell on grids and terrain, 1/500 of the larger
// side of a shape world.
double SplineSpacing(const Map& map) {
  if (const OccupancyGrid* grid = map.grid()) return 0.5 * grid->resolution();
  if (const ShapeWorld* world = map.world()) {
    return std::max(world->bounds().Width(), world->bounds().Height()) / 500.0;
  }
  return 0.5 * map.terrain()->cell_size();
}

}  // namespace

std::vector<std::string> SmoothingMethods() {
  return {"none", "cubic-spline", "bezier", "bounded-curvature"};
}

absl::StatusOr<SmoothingResult> Smooth(const std::string& method, const Map& map, const Path& raw,
                                       double clearance, double turning_radius) {
  SmoothingResult result;
  if (method == "none" || method.empty()) {
    result.path = raw;
  } else if (method == "cubic-spline") {
    if (raw.size() < 3) {
      result.path = raw;
    } else {
      CubicSpline spline;
      spline.Fit(raw, SplineEnd::kNotAKnot);
      spline.SampleBySpacing(SplineSpacing(map), result.path);
    }
  } else if (method == "bezier") {
    if (map.is_3d()) {
      return absl::InvalidArgumentError("smoothing: 'bezier' smooths planar paths only");
    }
    result.path =
        SmoothWithBezier(raw, DefaultBezierOptions(map, clearance), MakeCollisionChecker(map).get())
            .path;
  } else if (method == "bounded-curvature") {
    if (map.is_3d()) {
      return absl::InvalidArgumentError("smoothing: 'bounded-curvature' smooths planar paths only");
    }
    BoundedCurvatureOptions options;
    options.clearance = clearance;
    options.turning_radius = turning_radius > 0
                                 ? turning_radius
                                 : DefaultBezierOptions(map, clearance).min_turning_radius;
    BoundedCurvatureResult bounded =
        SmoothToTurningRadius(raw, options, *MakeCollisionChecker(map));
    result.path = std::move(bounded.path);
    result.within_turning_radius = bounded.corners_over == 0;
  } else {
    return absl::InvalidArgumentError(
        absl::StrCat("smoothing: unknown method '", method,
                     "'; available: ", absl::StrJoin(SmoothingMethods(), ", ")));
  }
  result.collision_free = MakeCollisionChecker(map)->PathFree(result.path, clearance);
  return result;
}

}  // namespace swarmplan
