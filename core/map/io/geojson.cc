// Polygon obstacles from GeoJSON (RFC 7946), read as a ShapeWorld.
//
// Rules:
// - The top level is a FeatureCollection. Each feature's geometry is a Polygon or a
//   MultiPolygon (every part becomes one obstacle); a feature with "geometry": null is skipped;
//   any other geometry type is an error.
// - Only outer rings: a polygon with holes is rejected (ignoring a hole would silently block
//   the free space inside it). Rings may be closed (the repeated closing vertex is dropped) and
//   of either orientation; positions may carry a third coordinate, which is ignored.
// - The world rectangle is the top-level "bounds" member [xmin, ymin, xmax, ymax] when present,
//   else a "bbox" member of four numbers, else the polygons' extent widened on every side by 5%
//   of its larger side.
// Coordinates are taken as plane x, y (no projection). Errors name the JSON path.

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "core/map/io/formats.h"
#include "core/map/io/json_util.h"
#include "core/map/io/text_util.h"

namespace swarmplan {
namespace {

using nlohmann::json;

constexpr double kExtentMargin = 0.05;

absl::Status Error(const std::string& path, const std::string& message) {
  return absl::InvalidArgumentError(absl::StrCat(path, ": ", message));
}

// Reads one GeoJSON polygon (an array of rings) at `path` into `out`.
absl::Status ReadPolygon(const json& rings, const std::string& path, const MapLimits& limits,
                         int64_t* vertices, std::vector<Polygon>* out) {
  if (!rings.is_array() || rings.empty()) {
    return Error(path, "a polygon must be a non-empty array of rings");
  }
  if (rings.size() > 1) {
    return Error(path, absl::StrCat("polygons with holes are not supported (", rings.size() - 1,
                                    " hole(s)); give the outer ring only"));
  }
  const json& ring = rings[0];
  const std::string ring_path = path + "[0]";
  if (!ring.is_array()) return Error(ring_path, "a ring must be an array of positions");
  *vertices += static_cast<int64_t>(ring.size());
  if (*vertices > limits.max_vertices) {
    return absl::ResourceExhaustedError(absl::StrCat(
        ring_path, ": polygons hold more than the limit of ", limits.max_vertices, " vertices"));
  }
  if (static_cast<int64_t>(out->size()) >= limits.max_obstacles) {
    return absl::ResourceExhaustedError(
        absl::StrCat(path, ": more than the limit of ", limits.max_obstacles, " obstacles"));
  }
  Polygon polygon;
  polygon.vertices.reserve(ring.size());
  for (size_t k = 0; k < ring.size(); ++k) {
    auto p = map_io_internal::JsonPoint(ring[k], absl::StrCat(ring_path, "[", k, "]"));
    if (!p.ok()) return p.status();
    polygon.vertices.push_back(*p);
  }
  if (auto s = map_io_internal::CleanRing(&polygon.vertices, ring_path); !s.ok()) return s;
  out->push_back(std::move(polygon));
  return absl::OkStatus();
}

absl::Status ReadFeature(const json& feature, const std::string& path, const MapLimits& limits,
                         int64_t* vertices, std::vector<Polygon>* out) {
  if (!feature.is_object() || !feature.contains("type") || feature["type"] != "Feature") {
    return Error(path, "must be an object with \"type\": \"Feature\"");
  }
  if (!feature.contains("geometry")) return Error(path + ".geometry", "missing");
  const json& geometry = feature["geometry"];
  if (geometry.is_null()) return absl::OkStatus();
  const std::string gpath = path + ".geometry";
  if (!geometry.is_object() || !geometry.contains("type") || !geometry["type"].is_string()) {
    return Error(gpath, "must be an object with a \"type\"");
  }
  const std::string type = geometry["type"].get<std::string>();
  if (type != "Polygon" && type != "MultiPolygon") {
    return Error(gpath + ".type",
                 absl::StrCat("\"", type, "\" is not supported (Polygon or MultiPolygon)"));
  }
  if (!geometry.contains("coordinates")) return Error(gpath + ".coordinates", "missing");
  const json& coordinates = geometry["coordinates"];
  const std::string cpath = gpath + ".coordinates";
  if (type == "Polygon") return ReadPolygon(coordinates, cpath, limits, vertices, out);
  if (!coordinates.is_array()) return Error(cpath, "a MultiPolygon must be an array of polygons");
  for (size_t i = 0; i < coordinates.size(); ++i) {
    if (auto s =
            ReadPolygon(coordinates[i], absl::StrCat(cpath, "[", i, "]"), limits, vertices, out);
        !s.ok()) {
      return s;
    }
  }
  return absl::OkStatus();
}

absl::StatusOr<Bounds2> WorldBounds(const json& root, const std::vector<Polygon>& polygons) {
  for (const char* key : {"bounds", "bbox"}) {
    if (!root.contains(key)) continue;
    auto b = map_io_internal::JsonBounds(root[key], key);
    if (!b.ok()) return b.status();
    return Bounds2{b->first, b->second};
  }
  if (polygons.empty()) {
    return absl::InvalidArgumentError(
        "features: no polygons and no \"bounds\" member: the world has no extent");
  }
  Bounds2 extent{polygons.front().vertices.front(), polygons.front().vertices.front()};
  for (const Polygon& polygon : polygons) {
    for (const Point2& p : polygon.vertices) {
      extent.min = extent.min.cwiseMin(p);
      extent.max = extent.max.cwiseMax(p);
    }
  }
  const double margin = kExtentMargin * std::max(extent.Width(), extent.Height());
  extent.min -= Point2(margin, margin);
  extent.max += Point2(margin, margin);
  return extent;
}

absl::StatusOr<ShapeWorld> ReadCollection(const json& root, const MapLimits& limits) {
  if (!root.is_object() || !root.contains("type") || root["type"] != "FeatureCollection") {
    return Error("type", "the top level must be a GeoJSON \"FeatureCollection\"");
  }
  if (!root.contains("features") || !root["features"].is_array()) {
    return Error("features", "must be an array");
  }
  const json& features = root["features"];
  std::vector<Polygon> polygons;
  int64_t vertices = 0;
  for (size_t i = 0; i < features.size(); ++i) {
    if (auto s = ReadFeature(features[i], absl::StrCat("features[", i, "]"), limits, &vertices,
                             &polygons);
        !s.ok()) {
      return s;
    }
  }
  auto bounds = WorldBounds(root, polygons);
  if (!bounds.ok()) return bounds.status();
  return ShapeWorld::Create(*bounds, {}, std::move(polygons), limits);
}

}  // namespace

absl::StatusOr<ShapeWorld> ParseGeoJson(const MapFile& file, const MapLimits& limits) {
  if (auto s = map_io_internal::CheckFileSize(file.name, file.bytes.size(), limits); !s.ok()) {
    return s;
  }
  auto root = map_io_internal::ParseJson(file.name, file.bytes);
  if (!root.ok()) return root.status();
  try {
    auto world = ReadCollection(*root, limits);
    if (!world.ok()) return map_io_internal::WithFile(file.name, world.status());
    return world;
  } catch (const nlohmann::json::exception& e) {
    return map_io_internal::Invalid(file.name, e.what());
  }
}

}  // namespace swarmplan
