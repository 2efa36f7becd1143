#include "core/map/shape_world.h"

#include <cmath>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "core/geometry/shape_distance_field.h"
#include "core/geometry/simple_polygon.h"

namespace swarmplan {
namespace {

double SignedArea(const std::vector<Point2>& v) {
  double area = 0.0;
  for (size_t i = 0; i < v.size(); ++i) {
    const Point2& a = v[i];
    const Point2& b = v[(i + 1) % v.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  return area / 2.0;
}

bool InRange(const Point2& p) { return InWorldRange(p.x()) && InWorldRange(p.y()); }

}  // namespace

absl::StatusOr<ShapeWorld> ShapeWorld::Create(Bounds2 bounds, std::vector<Circle> circles,
                                              std::vector<Polygon> polygons,
                                              const MapLimits& limits) {
  if (!InRange(bounds.min) || !InRange(bounds.max) || !(bounds.Width() > 0) ||
      !(bounds.Height() > 0)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "bounds: must be finite, within +-", kMaxWorldCoordinate, ", with max > min in x and y"));
  }
  if (static_cast<int64_t>(circles.size() + polygons.size()) > limits.max_obstacles) {
    return absl::ResourceExhaustedError(absl::StrCat(
        circles.size() + polygons.size(), " obstacles exceed the limit of ", limits.max_obstacles));
  }
  for (size_t i = 0; i < circles.size(); ++i) {
    const Circle& c = circles[i];
    if (!InRange(c.center) || !InWorldRange(c.radius) || c.radius <= 0) {
      return absl::InvalidArgumentError(
          absl::StrCat("circles[", i, "]: center must be finite and radius positive, within +-",
                       kMaxWorldCoordinate));
    }
  }
  int64_t vertices = 0;
  for (size_t i = 0; i < polygons.size(); ++i) {
    std::vector<Point2>& v = polygons[i].vertices;
    if (v.size() >= 2 && (v.front() - v.back()).norm() == 0.0) v.pop_back();  // closed ring
    vertices += static_cast<int64_t>(v.size());
    if (vertices > limits.max_vertices) {
      return absl::ResourceExhaustedError(
          absl::StrCat("polygons hold more than the limit of ", limits.max_vertices, " vertices"));
    }
    for (const Point2& p : v) {
      if (!InRange(p)) {
        return absl::InvalidArgumentError(
            absl::StrCat("polygons[", i, "]: vertex not finite or beyond +-", kMaxWorldCoordinate));
      }
    }
    if (v.size() < 3) {
      return absl::InvalidArgumentError(
          absl::StrCat("polygons[", i, "]: needs at least 3 distinct vertices, got ", v.size()));
    }
    const double area = SignedArea(v);
    if (area == 0.0 || !std::isfinite(area)) {
      return absl::InvalidArgumentError(absl::StrCat("polygons[", i, "]: has zero area"));
    }
    if (absl::Status s = CheckSimplePolygon(v); !s.ok()) {
      return absl::Status(s.code(), absl::StrCat("polygons[", i, "]: ", s.message()));
    }
    if (area < 0) std::reverse(v.begin(), v.end());
  }
  ShapeWorld world;
  world.bounds_ = bounds;
  world.circles_ = std::move(circles);
  world.polygons_ = std::move(polygons);
  world.distance_field_ = std::make_shared<const DistanceField>(
      ShapeDistanceField(world.bounds_, world.circles_, world.polygons_));
  return world;
}

}  // namespace swarmplan
