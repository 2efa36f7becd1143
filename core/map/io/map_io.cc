// Format names, guessing a format from a file name, and dispatch to the parsers in formats.h.

#include "core/map/io/map_io.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "core/map/io/formats.h"
#include "core/map/io/text_util.h"

namespace swarmplan {
namespace {

// Reads a whole file, refusing files larger than the limit before reading them.
absl::StatusOr<std::string> ReadFile(const std::string& path, const MapLimits& limits) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) {
    return absl::NotFoundError(absl::StrCat(path, ": cannot read: ", ec.message()));
  }
  if (auto s = map_io_internal::CheckFileSize(path, size, limits); !s.ok()) return s;
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat(path, ": cannot open"));
  std::string bytes(size, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<size_t>(in.gcount()) != size) {
    return absl::DataLossError(absl::StrCat(path, ": read ", in.gcount(), " of ", size, " bytes"));
  }
  return bytes;
}

template <typename T>
absl::StatusOr<Map> AsMap(absl::StatusOr<T> parsed) {
  if (!parsed.ok()) return parsed.status();
  return Map(std::move(*parsed));
}

}  // namespace

std::vector<std::string> MapFormats() {
  return {"ros-yaml-pgm", "movingai", "ascii",       "pgm",         "png",
          "shapes-json",  "geojson",  "terrain-asc", "terrain-pgm", "terrain-csv"};
}

absl::StatusOr<Map> ParseMap(const std::string& format, const std::vector<MapFile>& files,
                             const LoadOptions& options) {
  const size_t wanted = format == "ros-yaml-pgm" ? 2 : 1;
  bool known = false;
  for (const std::string& f : MapFormats()) known = known || f == format;
  if (!known) {
    return absl::InvalidArgumentError(absl::StrCat(
        "unknown map format \"", format, "\"; known formats: ", absl::StrJoin(MapFormats(), ", ")));
  }
  if (files.size() != wanted) {
    return absl::InvalidArgumentError(absl::StrCat(
        "format ", format, " needs ", wanted,
        wanted == 2 ? " files (the YAML first, then its image)" : " file", ", got ", files.size()));
  }
  for (const MapFile& f : files) {
    if (auto s = map_io_internal::CheckFileSize(f.name, f.bytes.size(), options.limits); !s.ok()) {
      return s;
    }
  }
  const MapFile& file = files.front();
  const MapLimits& limits = options.limits;
  if (format == "ros-yaml-pgm") return AsMap(ParseRosMap(files[0], files[1], limits));
  if (format == "pgm" || format == "png") return AsMap(ParseOccupancyImage(file, limits));
  if (format == "movingai") return AsMap(ParseMovingAiMap(file, limits));
  if (format == "ascii") return AsMap(ParseAsciiMap(file, limits));
  if (format == "shapes-json") return AsMap(ParseShapesJson(file, limits));
  if (format == "geojson") return AsMap(ParseGeoJson(file, limits));
  if (format == "terrain-asc") return AsMap(ParseTerrainAsc(file, options));
  if (format == "terrain-csv") return AsMap(ParseTerrainCsv(file, options));
  return AsMap(ParseTerrainImage(file, options));  // terrain-pgm
}

std::string GuessMapFormat(const std::string& path) {
  std::string ext = map_io_internal::Lower(std::filesystem::path(path).extension().string());
  if (ext == ".yaml" || ext == ".yml") return "ros-yaml-pgm";
  if (ext == ".map") return "movingai";
  if (ext == ".txt" || ext == ".ascii") return "ascii";
  if (ext == ".pgm") return "pgm";
  if (ext == ".png") return "png";
  if (ext == ".geojson") return "geojson";
  if (ext == ".json") return "shapes-json";
  if (ext == ".asc") return "terrain-asc";
  if (ext == ".csv") return "terrain-csv";
  return "";
}

absl::StatusOr<Map> LoadMapFile(const std::string& path, const std::string& format,
                                const LoadOptions& options) {
  const std::string fmt = format.empty() ? GuessMapFormat(path) : format;
  if (fmt.empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat(path, ": cannot tell the map format from the file name; name it (one of ",
                     absl::StrJoin(MapFormats(), ", "), ")"));
  }
  auto bytes = ReadFile(path, options.limits);
  if (!bytes.ok()) return bytes.status();
  std::vector<MapFile> files = {MapFile{path, std::move(*bytes)}};
  if (fmt == "ros-yaml-pgm") {
    auto image = RosMapImagePath(files.front());
    if (!image.ok()) return image.status();
    auto image_bytes = ReadFile(*image, options.limits);
    if (!image_bytes.ok()) return image_bytes.status();
    files.push_back(MapFile{*image, std::move(*image_bytes)});
  }
  return ParseMap(fmt, files, options);
}

absl::StatusOr<std::vector<Scenario>> LoadScenarioFile(const std::string& path) {
  auto bytes = ReadFile(path, MapLimits{});
  if (!bytes.ok()) return bytes.status();
  return ParseScenarios(path, *bytes);
}

}  // namespace swarmplan
