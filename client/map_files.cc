#include "client/map_files.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/output.h"
#include "core/map/io/formats.h"
#include "core/map/io/map_io.h"

namespace swarmplan::client {
namespace {

absl::StatusOr<std::string> ReadLocalFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    return absl::NotFoundError(absl::StrCat(path, ": no such file"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat(path, ": cannot read"));
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

absl::Status WriteLocalFile(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  out.close();
  if (!out) return absl::PermissionDeniedError(absl::StrCat(path, ": cannot write"));
  return absl::OkStatus();
}

std::string BaseName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

Point2 ToPoint2(const v1::Point& point) { return Point2(point.x(), point.y()); }

absl::StatusOr<Map> StructuredToMap(const v1::StructuredMap& map) {
  switch (map.kind_case()) {
    case v1::StructuredMap::kOccupancyGrid: {
      const v1::OccupancyGridData& grid = map.occupancy_grid();
      std::vector<int8_t> cells(grid.cells().begin(), grid.cells().end());
      absl::StatusOr<OccupancyGrid> built = OccupancyGrid::Create(
          grid.width(), grid.height(), std::move(cells),
          grid.resolution() > 0 ? grid.resolution() : 1.0, ToPoint2(grid.origin()));
      if (!built.ok()) return built.status();
      return Map(*std::move(built));
    }
    case v1::StructuredMap::kShapeWorld: {
      const v1::ShapeWorldData& world = map.shape_world();
      std::vector<Circle> circles;
      for (const v1::Circle& circle : world.circles()) {
        circles.push_back(Circle{ToPoint2(circle.center()), circle.radius()});
      }
      std::vector<Polygon> polygons;
      for (const v1::Polygon& polygon : world.polygons()) {
        Polygon converted;
        for (const v1::Point& vertex : polygon.vertices()) {
          converted.vertices.push_back(ToPoint2(vertex));
        }
        polygons.push_back(std::move(converted));
      }
      absl::StatusOr<ShapeWorld> built =
          ShapeWorld::Create(Bounds2{ToPoint2(world.min()), ToPoint2(world.max())},
                             std::move(circles), std::move(polygons));
      if (!built.ok()) return built.status();
      return Map(*std::move(built));
    }
    case v1::StructuredMap::kTerrain: {
      const v1::TerrainData& terrain = map.terrain();
      std::vector<double> heights(terrain.heights().begin(), terrain.heights().end());
      absl::StatusOr<Terrain> built = Terrain::Create(
          terrain.width(), terrain.depth(), std::move(heights),
          terrain.cell_size() > 0 ? terrain.cell_size() : 1.0, ToPoint2(terrain.origin()),
          terrain.has_ceiling() ? terrain.ceiling() : std::numeric_limits<double>::quiet_NaN());
      if (!built.ok()) return built.status();
      return Map(*std::move(built));
    }
    default:
      return absl::InvalidArgumentError("the server returned a structured map without data");
  }
}

}  // namespace

absl::StatusOr<v1::MapFiles> ReadMapFiles(const std::string& path, const std::string& format) {
  const std::string resolved = format.empty() ? GuessMapFormat(path) : format;
  if (resolved.empty()) {
    return absl::InvalidArgumentError(absl::StrCat(
        path, ": cannot tell the map format from the extension; give --format (one of ",
        absl::StrJoin(MapFormats(), ", "), ")"));
  }
  absl::StatusOr<std::string> bytes = ReadLocalFile(path);
  if (!bytes.ok()) return bytes.status();
  v1::MapFiles files;
  files.set_format(resolved);
  v1::MapFile* first = files.add_files();
  first->set_name(BaseName(path));
  first->set_content(*bytes);
  if (resolved == "ros-yaml-pgm") {
    absl::StatusOr<std::string> image_path = RosMapImagePath(MapFile{path, *bytes});
    if (!image_path.ok()) return image_path.status();
    absl::StatusOr<std::string> image = ReadLocalFile(*image_path);
    if (!image.ok()) {
      return absl::NotFoundError(
          absl::StrCat(path, ": the image it names cannot be read: ", image.status().message()));
    }
    v1::MapFile* second = files.add_files();
    second->set_name(BaseName(*image_path));
    second->set_content(*std::move(image));
  }
  return files;
}

absl::StatusOr<std::vector<std::string>> SaveMapSource(const v1::MapSource& source,
                                                       const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) return absl::PermissionDeniedError(absl::StrCat(dir, ": ", error.message()));
  std::vector<std::string> written;
  if (source.has_files()) {
    for (const v1::MapFile& file : source.files().files()) {
      const std::string path = (std::filesystem::path(dir) / BaseName(file.name())).string();
      absl::Status status = WriteLocalFile(path, file.content());
      if (!status.ok()) return status;
      written.push_back(path);
    }
  } else if (source.has_structured()) {
    const std::string path = (std::filesystem::path(dir) / "structured-map.json").string();
    absl::Status status = WriteLocalFile(path, ProtoToJson(source.structured()));
    if (!status.ok()) return status;
    written.push_back(path);
  }
  return written;
}

absl::StatusOr<Map> MapFromSource(const v1::MapSource& source) {
  if (source.has_structured()) return StructuredToMap(source.structured());
  if (!source.has_files()) {
    return absl::FailedPreconditionError(
        "the server returned no map content; render from the local file with --map-file");
  }
  std::vector<MapFile> files;
  for (const v1::MapFile& file : source.files().files()) {
    files.push_back(MapFile{file.name(), file.content()});
  }
  LoadOptions options;
  if (source.files().terrain_height_scale() > 0) {
    options.terrain_height_scale = source.files().terrain_height_scale();
  }
  if (source.files().has_terrain_ceiling()) {
    options.terrain_ceiling = source.files().terrain_ceiling();
  }
  return ParseMap(source.files().format(), files, options);
}

}  // namespace swarmplan::client
