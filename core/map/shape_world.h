#pragma once

#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/distance_field.h"
#include "core/map/limits.h"
#include "core/map/point.h"

namespace swarmplan {

struct Circle {
  Point2 center = Point2::Zero();
  double radius = 0.0;
};

// A simple polygon (no holes), vertices counter-clockwise, not closed (last != first).
struct Polygon {
  std::vector<Point2> vertices;
};

struct Bounds2 {
  Point2 min = Point2::Zero();
  Point2 max = Point2::Zero();
  bool Contains(const Point2& p) const {
    return p.x() >= min.x() && p.y() >= min.y() && p.x() <= max.x() && p.y() <= max.y();
  }
  double Width() const { return max.x() - min.x(); }
  double Height() const { return max.y() - min.y(); }
};

// A bounded rectangle with circle and polygon obstacles. Free space is the rectangle minus the
// union of the obstacles. Immutable; built once, shared between jobs. Create also rasterises
// the signed distance field of the obstacles once (ShapeDistanceField: 256 cells along the
// longer side, about 300 KB at most); the exact geometry still decides collisions.
class ShapeWorld {
 public:
  // Validates: finite coordinates, bounds with positive area, radii > 0, polygons with at least
  // three distinct vertices, non-zero area and no self-intersection (CheckSimplePolygon in
  // core/geometry/simple_polygon.h). Clockwise polygons are reoriented.
  static absl::StatusOr<ShapeWorld> Create(Bounds2 bounds, std::vector<Circle> circles,
                                           std::vector<Polygon> polygons,
                                           const MapLimits& limits = {});

  const Bounds2& bounds() const { return bounds_; }
  const std::vector<Circle>& circles() const { return circles_; }
  const std::vector<Polygon>& polygons() const { return polygons_; }
  size_t ObstacleCount() const { return circles_.size() + polygons_.size(); }
  const DistanceField& distance_field() const { return *distance_field_; }

 private:
  ShapeWorld() = default;
  Bounds2 bounds_;
  std::vector<Circle> circles_;
  std::vector<Polygon> polygons_;
  std::shared_ptr<const DistanceField> distance_field_;
};

}  // namespace swarmplan
