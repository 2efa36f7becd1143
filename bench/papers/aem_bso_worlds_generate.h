#pragma once

// The worlds of the AEM-BSO paper's path-planning tests (its section 5): 100 x 100, start
// (10, 10), goal (90, 90), a "simple" world with 10 circles and a "complex" one with 30. The
// paper does not publish its obstacles, so ours are drawn, seeded, and shipped as ShapeWorld
// JSON under bench/worlds/aem-bso-worlds/.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/point.h"
#include "core/map/shape_world.h"

namespace swarmplan::bench::aem_bso {

inline constexpr double kAemBsoSafeDistance = 1.5;  // the paper's d_safe

struct AemBsoWorldSpec {
  std::string name;  // the environment's name in the report, e.g. "simple"
  std::string file;  // file name under bench/worlds/aem-bso-worlds/
  int circles = 10;
  double min_radius = 4.0;
  double max_radius = 10.0;
  uint64_t seed = 1;  // first seed tried
};

// The paper's two environments, as we draw them.
const std::vector<AemBsoWorldSpec>& AemBsoWorldSpecs();

Point2 AemBsoStart();
Point2 AemBsoGoal();

// True when the segment a-b comes closer than `distance` to an obstacle of the world.
bool SegmentBlocked(const ShapeWorld& world, const Point2& a, const Point2& b, double distance);

// The first world, for seeds spec.seed, spec.seed + 1, ..., whose circles (centres and radii
// rounded to 0.01 so the JSON text is exact) keep start and goal 2 d_safe clear, block the
// straight start-goal segment (closer than d_safe) and leave a path keeping d_safe.
absl::StatusOr<ShapeWorld> MakeAemBsoWorld(const AemBsoWorldSpec& spec);

}  // namespace swarmplan::bench::aem_bso
