#pragma once

// Helpers shared by the JSON loaders (shapes-json, geojson): reading numbers and points with
// errors that name the JSON path. Internal to core/map/io.

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/point.h"
#include "nlohmann/json.hpp"

namespace swarmplan::map_io_internal {

// Parses JSON text; the error names the file and nlohmann's line/column.
absl::StatusOr<nlohmann::json> ParseJson(const std::string& file, const std::string& bytes);

// A finite number at `path`.
absl::StatusOr<double> JsonNumber(const nlohmann::json& value, const std::string& path);
// [x, y] (a third coordinate, as GeoJSON allows, is ignored) at `path`.
absl::StatusOr<Point2> JsonPoint(const nlohmann::json& value, const std::string& path);
// [xmin, ymin, xmax, ymax] with max > min at `path`.
absl::StatusOr<std::pair<Point2, Point2>> JsonBounds(const nlohmann::json& value,
                                                     const std::string& path);

// Turns a list of points into a polygon ring: drops repeated consecutive vertices and the
// repeated closing vertex, then checks at least 3 vertices, non-zero area and no self-intersection
// (CheckSimplePolygon). Errors name `path`.
absl::Status CleanRing(std::vector<Point2>* ring, const std::string& path);

}  // namespace swarmplan::map_io_internal
