#include <string>

#include "core/map/io/map_io.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

absl::StatusOr<Map> ParseShapes(const std::string& bytes, const MapLimits& limits = {}) {
  LoadOptions options;
  options.limits = limits;
  return ParseMap("shapes-json", {MapFile{"world.json", bytes}}, options);
}

TEST(MapIoShapesJsonTest, ParsesBoundsCirclesAndPolygons) {
  auto map = ParseShapes(R"({
    "name": "demo",
    "bounds": [0, -1, 10, 5],
    "circles": [{"center": [2, 2], "radius": 0.5}, {"center": [7, 1], "radius": 1}],
    "polygons": [[[4, 0], [4, 3], [5, 3], [5, 0], [4, 0]]]
  })");
  ASSERT_TRUE(map.ok()) << map.status();
  const ShapeWorld* world = map->world();
  ASSERT_NE(world, nullptr);
  EXPECT_EQ(world->bounds().min, Point2(0, -1));
  EXPECT_EQ(world->bounds().max, Point2(10, 5));
  ASSERT_EQ(world->circles().size(), 2u);
  EXPECT_EQ(world->circles()[1].center, Point2(7, 1));
  EXPECT_EQ(world->circles()[1].radius, 1.0);
  ASSERT_EQ(world->polygons().size(), 1u);
  // Closing vertex dropped; clockwise input reoriented counter-clockwise by ShapeWorld.
  EXPECT_EQ(world->polygons()[0].vertices.size(), 4u);
}

TEST(MapIoShapesJsonTest, CirclesAndPolygonsAreOptional) {
  auto map = ParseShapes(R"({"bounds": [0, 0, 1, 1]})");
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(map->world()->ObstacleCount(), 0u);
}

TEST(MapIoShapesJsonTest, RejectsBadInputNamingTheField) {
  struct Case {
    std::string bytes;
    std::string message;
  };
  const Case cases[] = {
      {R"({"bounds": [0, 0, 1)", "world.json: not valid JSON"},
      {R"([1, 2])", "world.json: the top level must be an object"},
      {R"({"circles": []})", "world.json: bounds: missing"},
      {R"({"bounds": [0, 0, 1]})", "world.json: bounds: must be [xmin, ymin, xmax, ymax]"},
      {R"({"bounds": [0, 0, 0, 1]})", "world.json: bounds: [xmin, ymin, xmax, ymax] needs"},
      {R"({"bounds": [0, "a", 2, 1]})", "world.json: bounds[1]: must be a number"},
      {R"({"bounds": [0, 0, 9, 9], "circle": []})", "world.json: circle: unknown member"},
      {R"({"bounds": [0, 0, 9, 9], "circles": {}})", "world.json: circles: must be an array"},
      {R"({"bounds": [0, 0, 9, 9], "circles": [{"center": [1, 1], "radius": 1},
          {"center": [1, 1], "radius": 1}, {"center": [1, 1], "radius": 1},
          {"center": [1, 1], "radius": -2}]})",
       "world.json: circles[3].radius: must be positive"},
      {R"({"bounds": [0, 0, 9, 9], "circles": [{"center": [1], "radius": 1}]})",
       "world.json: circles[0].center: must be a point [x, y]"},
      {R"({"bounds": [0, 0, 9, 9], "circles": [{"center": [1, 1]}]})",
       "world.json: circles[0].radius: missing"},
      {R"({"bounds": [0, 0, 9, 9], "circles": [{"center": [1, 1], "r": 1}]})",
       "world.json: circles[0].r: unknown member"},
      {R"({"bounds": [0, 0, 9, 9], "polygons": [[[0, 0], [1, 0], [0, 0]]]})",
       "world.json: polygons[0]: a polygon needs at least 3 distinct vertices, got 2"},
      {R"({"bounds": [0, 0, 9, 9], "polygons": [[[0, 0], [1, 0], [2, 0]]]})",
       "world.json: polygons[0]: polygon has zero area"},
      {R"({"bounds": [0, 0, 9, 9], "polygons": [[[1, 1], [2, 1], [1, 2]],
          [[0, 0], [4, 2], [4, 0], [0, 2], [-1, 1.5], [-1, 0.5]]]})",
       "world.json: polygons[1]: polygon is self-intersecting: edge 0 (0, 0)-(4, 2) and edge 2"},
      {R"({"bounds": [0, 0, 9, 9], "polygons": [[[0, 0], [1, 0], [1, null]]]})",
       "world.json: polygons[0][2][1]: must be a number"},
      {R"({"bounds": [0, 0, 9, 9], "polygons": [[[0, 0], [1, 0], [1, 1e999]]]})",
       "world.json: not valid JSON"},
  };
  for (const Case& c : cases) {
    auto map = ParseShapes(c.bytes);
    ASSERT_FALSE(map.ok()) << c.bytes;
    EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument) << c.bytes;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.bytes;
  }
}

TEST(MapIoShapesJsonTest, RespectsLimits) {
  const std::string three = R"({"bounds": [0, 0, 9, 9], "circles": [
      {"center": [1, 1], "radius": 1}, {"center": [2, 2], "radius": 1}],
      "polygons": [[[0, 0], [1, 0], [1, 1], [0, 1]]]})";
  MapLimits limits;
  limits.max_obstacles = 2;
  auto map = ParseShapes(three, limits);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(map.status().message(), HasSubstr("world.json"));

  limits = MapLimits{};
  limits.max_vertices = 3;
  map = ParseShapes(three, limits);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);

  limits = MapLimits{};
  limits.max_file_bytes = 20;
  map = ParseShapes(three, limits);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);
}

}  // namespace
}  // namespace swarmplan
