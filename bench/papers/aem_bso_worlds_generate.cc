#include "bench/papers/aem_bso_worlds_generate.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "core/geometry/primitives.h"
#include "core/graph/visibility_graph.h"
#include "core/map/generate.h"

namespace swarmplan::bench::aem_bso {
namespace {

constexpr int kMaxSeedsTried = 1000;
constexpr double kCircleTolerance = 0.01;

double Round2(double v) { return std::round(v * 100.0) / 100.0; }

}  // namespace

const std::vector<AemBsoWorldSpec>& AemBsoWorldSpecs() {
  static const std::vector<AemBsoWorldSpec>* const specs = new std::vector<AemBsoWorldSpec>{
      {"simple", "simple-10-circles.json", 10, 5.0, 10.0, 1},
      {"complex", "complex-30-circles.json", 30, 3.0, 7.0, 100},
  };
  return *specs;
}

Point2 AemBsoStart() { return Point2(10, 10); }
Point2 AemBsoGoal() { return Point2(90, 90); }

bool SegmentBlocked(const ShapeWorld& world, const Point2& a, const Point2& b, double distance) {
  for (const Circle& circle : world.circles()) {
    if (SegmentCircleDistance(a, b, circle) < distance) return true;
  }
  for (const Polygon& polygon : world.polygons()) {
    if (SegmentPolygonDistance(a, b, polygon.vertices) < distance) return true;
  }
  return false;
}

absl::StatusOr<ShapeWorld> MakeAemBsoWorld(const AemBsoWorldSpec& spec) {
  const Bounds2 bounds{Point2(0, 0), Point2(100, 100)};
  const Point2 start = AemBsoStart(), goal = AemBsoGoal();
  for (uint64_t seed = spec.seed; seed < spec.seed + kMaxSeedsTried; ++seed) {
    absl::StatusOr<ShapeWorld> drawn =
        RandomShapeWorld(bounds, spec.circles, spec.min_radius, spec.max_radius, seed,
                         {start, goal}, 2 * kAemBsoSafeDistance);
    if (!drawn.ok()) return drawn.status();
    std::vector<Circle> circles;
    for (const Circle& c : drawn->circles()) {
      circles.push_back({Point2(Round2(c.center.x()), Round2(c.center.y())), Round2(c.radius)});
    }
    absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(bounds, std::move(circles), {});
    if (!world.ok()) return world.status();
    if (SegmentBlocked(*world, start, start, 2 * kAemBsoSafeDistance) ||
        SegmentBlocked(*world, goal, goal, 2 * kAemBsoSafeDistance) ||
        !SegmentBlocked(*world, start, goal, kAemBsoSafeDistance)) {
      continue;
    }
    if (!ShortestPathVisibility(*world, start, goal, kAemBsoSafeDistance, kCircleTolerance).ok()) {
      continue;
    }
    return world;
  }
  return absl::NotFoundError(absl::StrCat("aem-bso-worlds: no usable ", spec.name, " world in ",
                                          kMaxSeedsTried, " seeds from ", spec.seed));
}

}  // namespace swarmplan::bench::aem_bso
