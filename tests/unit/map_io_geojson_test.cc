#include <string>

#include "core/map/io/map_io.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

absl::StatusOr<Map> ParseGeo(const std::string& bytes, const MapLimits& limits = {}) {
  LoadOptions options;
  options.limits = limits;
  return ParseMap("geojson", {MapFile{"world.geojson", bytes}}, options);
}

std::string Collection(const std::string& features, const std::string& extra = "") {
  return R"({"type": "FeatureCollection", )" + extra + R"("features": [)" + features + "]}";
}

constexpr char kSquare[] =
    R"({"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
        "coordinates": [[[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]]]}})";

TEST(MapIoGeoJsonTest, ReadsPolygonsAndBoundsMember) {
  auto map = ParseGeo(Collection(kSquare, R"("bounds": [-1, -1, 5, 4], )"));
  ASSERT_TRUE(map.ok()) << map.status();
  const ShapeWorld* world = map->world();
  ASSERT_NE(world, nullptr);
  EXPECT_EQ(world->bounds().min, Point2(-1, -1));
  EXPECT_EQ(world->bounds().max, Point2(5, 4));
  ASSERT_EQ(world->polygons().size(), 1u);
  EXPECT_EQ(world->polygons()[0].vertices.size(), 4u);  // closing vertex dropped
  EXPECT_TRUE(world->circles().empty());
}

TEST(MapIoGeoJsonTest, ReadsMultiPolygonsAndDerivesBoundsFromExtent) {
  const std::string multi = R"({"type": "Feature", "geometry": {"type": "MultiPolygon",
      "coordinates": [[[[10, 0], [12, 0], [12, 1], [10, 0]]],
                      [[[0, 0, 5], [1, 0, 5], [0, 2, 5], [0, 0, 5]]]]}})";
  auto map =
      ParseGeo(Collection(std::string(multi) + R"(, {"type": "Feature", "geometry": null})"));
  ASSERT_TRUE(map.ok()) << map.status();
  const ShapeWorld* world = map->world();
  EXPECT_EQ(world->polygons().size(), 2u);
  // Extent [0, 0] - [12, 2] widened by 5% of 12 = 0.6 on every side.
  EXPECT_NEAR(world->bounds().min.x(), -0.6, 1e-12);
  EXPECT_NEAR(world->bounds().min.y(), -0.6, 1e-12);
  EXPECT_NEAR(world->bounds().max.x(), 12.6, 1e-12);
  EXPECT_NEAR(world->bounds().max.y(), 2.6, 1e-12);
}

TEST(MapIoGeoJsonTest, RejectsBadInputNamingThePath) {
  struct Case {
    std::string bytes;
    std::string message;
  };
  const Case cases[] = {
      {"{", "world.geojson: not valid JSON"},
      {R"({"type": "Feature"})", "world.geojson: type: the top level must be"},
      {R"({"type": "FeatureCollection"})", "world.geojson: features: must be an array"},
      {Collection(""), "world.geojson: features: no polygons and no \"bounds\""},
      {Collection(std::string(kSquare) + R"(, {"type": "Feature", "geometry": {"type":
           "LineString", "coordinates": [[0, 0], [1, 1]]}})"),
       "world.geojson: features[1].geometry.type: \"LineString\" is not supported"},
      {Collection(R"({"type": "Feature", "geometry": {"type": "Polygon", "coordinates":
           [[[0, 0], [4, 0], [4, 4], [0, 0]], [[1, 1], [2, 1], [2, 2], [1, 1]]]}})"),
       "world.geojson: features[0].geometry.coordinates: polygons with holes are not supported"},
      {Collection(R"({"type": "Feature", "geometry": {"type": "Polygon", "coordinates":
           [[[0, 0], [4, 0], [0, 0]]]}})"),
       "world.geojson: features[0].geometry.coordinates[0]: a polygon needs at least 3"},
      {Collection(R"({"type": "Feature", "geometry": {"type": "Polygon", "coordinates":
           [[[0, 0], [4, "x"], [4, 4], [0, 0]]]}})"),
       "world.geojson: features[0].geometry.coordinates[0][1][1]: must be a number"},
      {Collection(R"({"type": "Feature", "geometry": {"type": "Polygon"}})"),
       "world.geojson: features[0].geometry.coordinates: missing"},
      {Collection(R"({"type": "Thing"})"), "world.geojson: features[0]: must be an object"},
      {Collection(kSquare, R"("bounds": [0, 0, 1], )"),
       "world.geojson: bounds: must be [xmin, ymin, xmax, ymax]"},
      // Unequal lobes: the signed area is not zero, the ring crosses itself.
      {Collection(std::string(kSquare) + R"(, {"type": "Feature", "geometry": {"type":
           "MultiPolygon", "coordinates": [[[[5, 5], [6, 5], [5, 6], [5, 5]]],
           [[[0, 0], [4, 2], [4, 0], [0, 2], [-1, 1.5], [-1, 0.5], [0, 0]]]]}})"),
       "world.geojson: features[1].geometry.coordinates[1][0]: polygon is self-intersecting: "
       "edge 0 (0, 0)-(4, 2) and edge 2 (4, 0)-(0, 2) cross or touch"},
      // Two squares joined at one vertex.
      {Collection(R"({"type": "Feature", "geometry": {"type": "Polygon", "coordinates":
           [[[0, 0], [1, 0], [1, 1], [2, 1], [2, 2], [1, 2], [1, 1], [0, 1], [0, 0]]]}})"),
       "world.geojson: features[0].geometry.coordinates[0]: polygon is self-intersecting"},
  };
  for (const Case& c : cases) {
    auto map = ParseGeo(c.bytes);
    ASSERT_FALSE(map.ok()) << c.bytes;
    EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument) << c.bytes;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.bytes;
  }
}

TEST(MapIoGeoJsonTest, RespectsLimits) {
  MapLimits limits;
  limits.max_vertices = 4;
  auto map = ParseGeo(Collection(std::string(kSquare) + ", " + kSquare), limits);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(map.status().message(), HasSubstr("world.geojson"));

  limits = MapLimits{};
  limits.max_obstacles = 1;
  map = ParseGeo(Collection(std::string(kSquare) + ", " + kSquare), limits);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);
}

TEST(MapIoGeoJsonTest, LoadsEveryBenchmarkWorld) {
  SWARMPLAN_REQUIRE_BENCHMARKS("polygons");
  struct World {
    const char* name;
    size_t obstacles;
    size_t vertices;
    double xmax;
    double ymax;
  };
  const World worlds[] = {{"parking1", 13, 224, 18.658882, 14.412246},
                          {"parking3", 18, 259, 36.69226, 26.694475},
                          {"warehouse", 88, 1760, 85.772506, 80.471351},
                          {"warehouse2", 80, 1600, 124.48051, 81.300697}};
  for (const World& w : worlds) {
    auto map = LoadMapFile(testing::BenchmarksDir() + "/polygons/" + w.name + ".geojson");
    ASSERT_TRUE(map.ok()) << map.status();
    const ShapeWorld* world = map->world();
    ASSERT_NE(world, nullptr);
    EXPECT_EQ(world->polygons().size(), w.obstacles) << w.name;
    size_t vertices = 0;
    for (const Polygon& p : world->polygons()) {
      vertices += p.vertices.size();
      for (const Point2& v : p.vertices) EXPECT_TRUE(world->bounds().Contains(v)) << w.name;
    }
    EXPECT_EQ(vertices, w.vertices) << w.name;
    EXPECT_EQ(world->bounds().min, Point2(0, 0)) << w.name;
    EXPECT_EQ(world->bounds().max, Point2(w.xmax, w.ymax)) << w.name;
  }
}

}  // namespace
}  // namespace swarmplan
