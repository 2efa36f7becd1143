// ShapeWorld JSON. The schema:
//
//   {
//     "name": "optional, ignored",
//     "bounds": [xmin, ymin, xmax, ymax],                  required, xmax > xmin, ymax > ymin
//     "circles": [{"center": [x, y], "radius": r}, ...],  optional, r > 0
//     "polygons": [[[x, y], [x, y], [x, y], ...], ...]    optional, >= 3 distinct vertices,
//   }                                                      either orientation, closed or not
//
// Numbers must be finite. Other members are rejected (a misspelt "circle" would otherwise give
// an empty world). Errors name the JSON path, e.g. "circles[3].radius: must be positive".

#include "absl/strings/str_cat.h"
#include "core/map/io/formats.h"
#include "core/map/io/json_util.h"
#include "core/map/io/text_util.h"

namespace swarmplan {
namespace {

using map_io_internal::JsonNumber;
using map_io_internal::JsonPoint;
using nlohmann::json;

absl::StatusOr<Circle> ReadCircle(const json& value, const std::string& path) {
  if (!value.is_object()) {
    return absl::InvalidArgumentError(
        absl::StrCat(path, ": must be {\"center\": [x, y], \"radius\": r}"));
  }
  for (const auto& [key, unused] : value.items()) {
    if (key != "center" && key != "radius") {
      return absl::InvalidArgumentError(
          absl::StrCat(path, ".", key, ": unknown member (a circle has center and radius)"));
    }
  }
  if (!value.contains("center"))
    return absl::InvalidArgumentError(absl::StrCat(path, ".center: missing"));
  if (!value.contains("radius"))
    return absl::InvalidArgumentError(absl::StrCat(path, ".radius: missing"));
  auto center = JsonPoint(value["center"], path + ".center");
  if (!center.ok()) return center.status();
  auto radius = JsonNumber(value["radius"], path + ".radius");
  if (!radius.ok()) return radius.status();
  if (*radius <= 0)
    return absl::InvalidArgumentError(absl::StrCat(path, ".radius: must be positive"));
  return Circle{*center, *radius};
}

absl::StatusOr<ShapeWorld> ParseShapes(const json& root, const MapLimits& limits) {
  if (!root.is_object()) {
    return absl::InvalidArgumentError("the top level must be an object with \"bounds\"");
  }
  for (const auto& [key, unused] : root.items()) {
    if (key != "bounds" && key != "circles" && key != "polygons" && key != "name") {
      return absl::InvalidArgumentError(
          absl::StrCat(key, ": unknown member (known: bounds, circles, polygons, name)"));
    }
  }
  if (!root.contains("bounds")) return absl::InvalidArgumentError("bounds: missing");
  auto bounds = map_io_internal::JsonBounds(root["bounds"], "bounds");
  if (!bounds.ok()) return bounds.status();
  const json empty = json::array();
  const json& circles_json = root.contains("circles") ? root["circles"] : empty;
  const json& polygons_json = root.contains("polygons") ? root["polygons"] : empty;
  if (!circles_json.is_array()) return absl::InvalidArgumentError("circles: must be an array");
  if (!polygons_json.is_array()) return absl::InvalidArgumentError("polygons: must be an array");
  const int64_t obstacles = static_cast<int64_t>(circles_json.size() + polygons_json.size());
  if (obstacles > limits.max_obstacles) {
    return absl::ResourceExhaustedError(
        absl::StrCat(obstacles, " obstacles exceed the limit of ", limits.max_obstacles));
  }
  std::vector<Circle> circles;
  circles.reserve(circles_json.size());
  for (size_t i = 0; i < circles_json.size(); ++i) {
    auto c = ReadCircle(circles_json[i], absl::StrCat("circles[", i, "]"));
    if (!c.ok()) return c.status();
    circles.push_back(*c);
  }
  std::vector<Polygon> polygons;
  polygons.reserve(polygons_json.size());
  int64_t vertices = 0;
  for (size_t i = 0; i < polygons_json.size(); ++i) {
    const std::string path = absl::StrCat("polygons[", i, "]");
    const json& ring_json = polygons_json[i];
    if (!ring_json.is_array()) {
      return absl::InvalidArgumentError(absl::StrCat(path, ": must be an array of [x, y] points"));
    }
    vertices += static_cast<int64_t>(ring_json.size());
    if (vertices > limits.max_vertices) {
      return absl::ResourceExhaustedError(
          absl::StrCat("polygons: more than the limit of ", limits.max_vertices, " vertices"));
    }
    Polygon polygon;
    polygon.vertices.reserve(ring_json.size());
    for (size_t k = 0; k < ring_json.size(); ++k) {
      auto p = JsonPoint(ring_json[k], absl::StrCat(path, "[", k, "]"));
      if (!p.ok()) return p.status();
      polygon.vertices.push_back(*p);
    }
    if (auto s = map_io_internal::CleanRing(&polygon.vertices, path); !s.ok()) return s;
    polygons.push_back(std::move(polygon));
  }
  return ShapeWorld::Create(Bounds2{bounds->first, bounds->second}, std::move(circles),
                            std::move(polygons), limits);
}

}  // namespace

absl::StatusOr<ShapeWorld> ParseShapesJson(const MapFile& file, const MapLimits& limits) {
  if (auto s = map_io_internal::CheckFileSize(file.name, file.bytes.size(), limits); !s.ok()) {
    return s;
  }
  auto root = map_io_internal::ParseJson(file.name, file.bytes);
  if (!root.ok()) return root.status();
  try {
    auto world = ParseShapes(*root, limits);
    if (!world.ok()) return map_io_internal::WithFile(file.name, world.status());
    return world;
  } catch (const nlohmann::json::exception& e) {
    return map_io_internal::Invalid(file.name, e.what());
  }
}

}  // namespace swarmplan
