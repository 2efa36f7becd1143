#include "core/map/io/map_writers.h"

#include <string>

#include "core/map/io/map_io.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

TEST(MapWritersTest, AsciiMapWritesRowsFromYZeroAndReadsBackTheSameCells) {
  // 3 x 2: the blocked cells are (1, 0) and (2, 1).
  absl::StatusOr<OccupancyGrid> grid =
      OccupancyGrid::Create(3, 2,
                            {OccupancyGrid::kFree, OccupancyGrid::kOccupied, OccupancyGrid::kFree,
                             OccupancyGrid::kFree, OccupancyGrid::kFree, OccupancyGrid::kOccupied},
                            1.0, Point2::Zero());
  ASSERT_TRUE(grid.ok()) << grid.status();
  const std::string text = FormatAsciiMap(*grid);
  EXPECT_EQ(text, ".#.\n..#\n");
  absl::StatusOr<Map> back = ParseMap("ascii", {MapFile{"grid.txt", text}});
  ASSERT_TRUE(back.ok()) << back.status();
  ASSERT_NE(back->grid(), nullptr);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) EXPECT_EQ(back->grid()->IsBlocked(x, y), grid->IsBlocked(x, y));
  }
}

TEST(MapWritersTest, ShapesJsonUsesShortestNumbersAndReadsBackExactly) {
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(
      Bounds2{Point2(0, 0), Point2(100, 50)}, {Circle{Point2(35.09, 2.1), 0.1 + 0.2}},
      {Polygon{{Point2(10, 10), Point2(20, 10), Point2(15, 18.5)}}});
  ASSERT_TRUE(world.ok()) << world.status();
  const std::string text = FormatShapesJson(*world, "a \"quoted\" name");
  EXPECT_EQ(text,
            "{\n"
            "  \"name\": \"a \\\"quoted\\\" name\",\n"
            "  \"bounds\": [0, 0, 100, 50],\n"
            "  \"circles\": [\n"
            "    {\"center\": [35.09, 2.1], \"radius\": 0.30000000000000004}\n"
            "  ],\n"
            "  \"polygons\": [\n"
            "    [[10, 10], [20, 10], [15, 18.5]]\n"
            "  ]\n"
            "}\n");
  absl::StatusOr<Map> back = ParseMap("shapes-json", {MapFile{"world.json", text}});
  ASSERT_TRUE(back.ok()) << back.status();
  const ShapeWorld* read = back->world();
  ASSERT_NE(read, nullptr);
  ASSERT_EQ(read->circles().size(), 1u);
  EXPECT_EQ(read->circles()[0].center, world->circles()[0].center);
  EXPECT_EQ(read->circles()[0].radius, world->circles()[0].radius);
  ASSERT_EQ(read->polygons().size(), 1u);
  EXPECT_EQ(read->polygons()[0].vertices, world->polygons()[0].vertices);
}

}  // namespace
}  // namespace swarmplan
