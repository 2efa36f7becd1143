#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/limits.h"
#include "core/map/map.h"

namespace swarmplan {

// A file given by name and content (an upload, or a file read from disk).
struct MapFile {
  std::string name;
  std::string bytes;
};

// The formats swarmplan reads, by the names the API and the CLI use:
//   ros-yaml-pgm  ROS map_server YAML + its PGM (P2/P5) or PNG image (two files: YAML first)
//   movingai      Moving AI .map
//   ascii         ASCII art: '.' free, '#' or '@' blocked
//   pgm, png      an image alone, read as map_server would with default thresholds
//   shapes-json   ShapeWorld JSON (bounds, circles, polygons)
//   geojson       polygons from a GeoJSON FeatureCollection (bounds member or their extent)
//   terrain-asc   ESRI ASCII grid
//   terrain-pgm   height image (grey level = height)
//   terrain-csv   CSV of heights, first line the northernmost row
std::vector<std::string> MapFormats();

struct LoadOptions {
  MapLimits limits;
  // Terrain: height units per grey level (terrain-pgm) and an optional ceiling (NaN: derived).
  double terrain_height_scale = 1.0;
  double terrain_ceiling = std::numeric_limits<double>::quiet_NaN();
};

// Parses a map from file contents. INVALID_ARGUMENT naming the file, line or field on bad
// input; RESOURCE_EXHAUSTED when the map exceeds the limits. Never returns a partial map.
absl::StatusOr<Map> ParseMap(const std::string& format, const std::vector<MapFile>& files,
                             const LoadOptions& options = {});

// The format a file name suggests ("" when none): .yaml -> ros-yaml-pgm, .map -> movingai, ...
std::string GuessMapFormat(const std::string& path);

// Reads a map from disk. For ros-yaml-pgm the image named in the YAML is read relative to it.
// An empty format is guessed from the extension.
absl::StatusOr<Map> LoadMapFile(const std::string& path, const std::string& format = "",
                                const LoadOptions& options = {});

// One problem of a Moving AI .scen file. Coordinates are cells: x the column, y the row.
struct Scenario {
  int bucket = 0;
  std::string map_name;
  int width = 0;
  int height = 0;
  Cell start;
  Cell goal;
  double optimal_length = 0.0;
};

absl::StatusOr<std::vector<Scenario>> ParseScenarios(const std::string& name,
                                                     const std::string& bytes);
absl::StatusOr<std::vector<Scenario>> LoadScenarioFile(const std::string& path);

}  // namespace swarmplan
