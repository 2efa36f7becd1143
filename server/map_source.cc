#include "server/map_source.h"

#include <openssl/evp.h>

#include <cmath>

#include "absl/status/status.h"
#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "server/proto_convert.h"

namespace swarmplan::server {
namespace {

absl::StatusOr<Map> BuildGrid(const v1::OccupancyGridData& g, const MapLimits& limits) {
  if (g.width() <= 0 || g.height() <= 0) {
    return absl::InvalidArgumentError(
        "source.structured.occupancy_grid: width and height must be > 0");
  }
  const int64_t cells = int64_t{g.width()} * g.height();
  if (cells > limits.max_cells) {
    return absl::ResourceExhaustedError(absl::StrCat("source.structured.occupancy_grid: ", cells,
                                                     " cells exceed the server's limit of ",
                                                     limits.max_cells));
  }
  if (static_cast<int64_t>(g.cells().size()) != cells) {
    return absl::InvalidArgumentError(
        absl::StrCat("source.structured.occupancy_grid.cells: expected width * height = ", cells,
                     " bytes, got ", g.cells().size()));
  }
  std::vector<int8_t> values(g.cells().begin(), g.cells().end());
  for (size_t i = 0; i < values.size(); ++i) {
    if (values[i] < -1 || values[i] > 100) {
      return absl::InvalidArgumentError(absl::StrCat("source.structured.occupancy_grid.cells[", i,
                                                     "]: value ", int{values[i]},
                                                     " is not -1 or 0..100"));
    }
  }
  const double resolution = g.resolution() == 0 ? 1.0 : g.resolution();
  absl::StatusOr<OccupancyGrid> grid =
      OccupancyGrid::Create(g.width(), g.height(), std::move(values), resolution,
                            Point2(g.origin().x(), g.origin().y()), limits);
  if (!grid.ok()) return grid.status();
  return Map(std::move(*grid));
}

absl::StatusOr<Map> BuildWorld(const v1::ShapeWorldData& w, const MapLimits& limits) {
  Bounds2 bounds{Point2(w.min().x(), w.min().y()), Point2(w.max().x(), w.max().y())};
  std::vector<Circle> circles;
  for (const v1::Circle& c : w.circles()) {
    circles.push_back(Circle{Point2(c.center().x(), c.center().y()), c.radius()});
  }
  std::vector<Polygon> polygons;
  for (const v1::Polygon& p : w.polygons()) {
    Polygon poly;
    for (const v1::Point& v : p.vertices()) poly.vertices.emplace_back(v.x(), v.y());
    polygons.push_back(std::move(poly));
  }
  absl::StatusOr<ShapeWorld> world =
      ShapeWorld::Create(bounds, std::move(circles), std::move(polygons), limits);
  if (!world.ok()) {
    return absl::Status(world.status().code(),
                        absl::StrCat("source.structured.shape_world: ", world.status().message()));
  }
  return Map(std::move(*world));
}

absl::StatusOr<Map> BuildTerrain(const v1::TerrainData& t, const MapLimits& limits) {
  if (t.width() <= 0 || t.depth() <= 0) {
    return absl::InvalidArgumentError("source.structured.terrain: width and depth must be > 0");
  }
  const int64_t cells = int64_t{t.width()} * t.depth();
  if (cells > limits.max_cells) {
    return absl::ResourceExhaustedError(absl::StrCat("source.structured.terrain: ", cells,
                                                     " cells exceed the server's limit of ",
                                                     limits.max_cells));
  }
  if (static_cast<int64_t>(t.heights_size()) != cells) {
    return absl::InvalidArgumentError(
        absl::StrCat("source.structured.terrain.heights: expected width * depth = ", cells,
                     " values, got ", t.heights_size()));
  }
  std::vector<double> heights(t.heights().begin(), t.heights().end());
  const double ceiling =
      t.has_ceiling() && t.ceiling() != 0 ? t.ceiling() : std::numeric_limits<double>::quiet_NaN();
  absl::StatusOr<Terrain> terrain = Terrain::Create(
      t.width(), t.depth(), std::move(heights), t.cell_size() == 0 ? 1.0 : t.cell_size(),
      Point2(t.origin().x(), t.origin().y()), ceiling, limits);
  if (!terrain.ok()) {
    return absl::Status(terrain.status().code(),
                        absl::StrCat("source.structured.terrain: ", terrain.status().message()));
  }
  return Map(std::move(*terrain));
}

}  // namespace

std::string SourceFormat(const v1::MapSource& source) {
  return source.has_files() ? source.files().format() : "structured";
}

absl::StatusOr<Map> BuildMap(const v1::MapSource& source, const LoadOptions& options) {
  switch (source.source_case()) {
    case v1::MapSource::kFiles: {
      const v1::MapFiles& f = source.files();
      if (f.format().empty()) {
        return absl::InvalidArgumentError(
            "source.files.format: required (one of the formats "
            "listed in maps.proto)");
      }
      if (f.files().empty()) return absl::InvalidArgumentError("source.files.files: empty");
      std::vector<MapFile> files;
      for (const v1::MapFile& file : f.files()) files.push_back({file.name(), file.content()});
      LoadOptions opts = options;
      if (f.terrain_height_scale() != 0) opts.terrain_height_scale = f.terrain_height_scale();
      if (f.has_terrain_ceiling()) opts.terrain_ceiling = f.terrain_ceiling();
      return ParseMap(f.format(), files, opts);
    }
    case v1::MapSource::kStructured: {
      const v1::StructuredMap& s = source.structured();
      switch (s.kind_case()) {
        case v1::StructuredMap::kOccupancyGrid:
          return BuildGrid(s.occupancy_grid(), options.limits);
        case v1::StructuredMap::kShapeWorld:
          return BuildWorld(s.shape_world(), options.limits);
        case v1::StructuredMap::kTerrain:
          return BuildTerrain(s.terrain(), options.limits);
        case v1::StructuredMap::KIND_NOT_SET:
          break;
      }
      return absl::InvalidArgumentError(
          "source.structured: set one of occupancy_grid, shape_world, terrain");
    }
    case v1::MapSource::SOURCE_NOT_SET:
      break;
  }
  return absl::InvalidArgumentError("source: set files (format + file bytes) or structured");
}

v1::MapInfo DescribeMap(const Map& map) {
  v1::MapInfo info;
  info.set_kind(ToProto(map.kind()));
  if (const OccupancyGrid* g = map.grid()) {
    info.set_width(g->width());
    info.set_height(g->height());
    info.set_resolution(g->resolution());
    *info.mutable_min() = ToProto(Point3(g->origin().x(), g->origin().y(), 0));
    const Point2 max = g->origin() + Point2(g->width(), g->height()) * g->resolution();
    *info.mutable_max() = ToProto(Point3(max.x(), max.y(), 0));
    info.set_obstacle_count(g->BlockedCount());
  } else if (const ShapeWorld* w = map.world()) {
    *info.mutable_min() = ToProto(Point3(w->bounds().min.x(), w->bounds().min.y(), 0));
    *info.mutable_max() = ToProto(Point3(w->bounds().max.x(), w->bounds().max.y(), 0));
    info.set_obstacle_count(static_cast<int64_t>(w->ObstacleCount()));
  } else if (const Terrain* t = map.terrain()) {
    info.set_width(t->width());
    info.set_height(t->depth());
    info.set_resolution(t->cell_size());
    *info.mutable_min() = ToProto(Point3(t->min_xy().x(), t->min_xy().y(), t->min_height()));
    *info.mutable_max() = ToProto(Point3(t->max_xy().x(), t->max_xy().y(), t->ceiling()));
    int64_t no_data = 0;
    for (double h : t->heights()) no_data += std::isnan(h) ? 1 : 0;
    info.set_obstacle_count(no_data);
  }
  return info;
}

std::string ContentHash(const std::string& serialized_source) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_Digest(serialized_source.data(), serialized_source.size(), digest, &length, EVP_sha256(),
             nullptr);
  return absl::BytesToHexString(
      std::string(reinterpret_cast<const char*>(digest), static_cast<size_t>(length)));
}

}  // namespace swarmplan::server
