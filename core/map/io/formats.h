#pragma once

// One parser per file format; map_io.cc dispatches to them by format name. Every parser checks
// the limits before allocating and returns INVALID_ARGUMENT (or RESOURCE_EXHAUSTED) with a
// message that starts with the file name and names the line or field.

#include <cstddef>
#include <string>

#include "absl/status/statusor.h"
#include "core/map/io/map_io.h"
#include "core/map/occupancy_grid.h"
#include "core/map/shape_world.h"
#include "core/map/terrain.h"

namespace swarmplan {

// Moving AI .map: row 0 of the file is y = 0 (y grows downward, as in .scen files); '.', 'G'
// and 'S' are free (0), every other character blocked (100). Resolution 1, origin 0.
absl::StatusOr<OccupancyGrid> ParseMovingAiMap(const MapFile& file, const MapLimits& limits);

// ASCII art: '.' free, '#' or '@' blocked; no other character (not even a space: trailing
// spaces from an editor would silently change a row). The first line is y = 0, like Moving AI.
// All rows the same length; blank lines after the last row are ignored.
absl::StatusOr<OccupancyGrid> ParseAsciiMap(const MapFile& file, const MapLimits& limits);

// ShapeWorld JSON; the schema is in shapes_json.cc.
absl::StatusOr<ShapeWorld> ParseShapesJson(const MapFile& file, const MapLimits& limits);

// GeoJSON FeatureCollection of Polygon / MultiPolygon features; the rules are in geojson.cc.
absl::StatusOr<ShapeWorld> ParseGeoJson(const MapFile& file, const MapLimits& limits);

// ESRI ASCII grid. Grid row y = nrows - 1 - data line (y grows north); origin is the lower-left
// corner of the lower-left cell; cells equal to NODATA_value are NaN.
absl::StatusOr<Terrain> ParseTerrainAsc(const MapFile& file, const LoadOptions& options);

// CSV of heights, first line the northernmost row; "nan" marks a cell without data.
absl::StatusOr<Terrain> ParseTerrainCsv(const MapFile& file, const LoadOptions& options);

// Height image (PGM P2/P5 or PNG): height = grey level * options.terrain_height_scale, with the
// grey level in the image's own range (0..255, or 0..maxval / 0..65535 for 16-bit images).
absl::StatusOr<Terrain> ParseTerrainImage(const MapFile& file, const LoadOptions& options);

// The most bytes a ROS map YAML may have. Its seven short keys take a few hundred bytes, and
// the YAML parser's time and memory grow with the document, so a larger one is refused
// (RESOURCE_EXHAUSTED naming the file) before it is parsed.
inline constexpr size_t kMaxRosYamlBytes = 4096;

// ROS map_server YAML and the image it names (its content given separately).
absl::StatusOr<OccupancyGrid> ParseRosMap(const MapFile& yaml, const MapFile& image,
                                          const MapLimits& limits);

// The image a ROS map YAML names, resolved against the YAML's directory (as map_server does).
absl::StatusOr<std::string> RosMapImagePath(const MapFile& yaml);

// An image alone (PGM or PNG), read as map_server would with its defaults: resolution 1,
// origin 0, negate 0, occupied_thresh 0.65, free_thresh 0.196, trinary.
absl::StatusOr<OccupancyGrid> ParseOccupancyImage(const MapFile& image, const MapLimits& limits);

}  // namespace swarmplan
