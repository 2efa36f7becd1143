#include "core/map/generate.h"

#include <cmath>

#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

TEST(GenerateTest, RandomGridHasTheExactObstacleCountAndIsReproducible) {
  auto a = RandomGrid(40, 30, 0.25, 7);
  ASSERT_TRUE(a.ok()) << a.status();
  EXPECT_EQ(a->width(), 40);
  EXPECT_EQ(a->height(), 30);
  EXPECT_EQ(a->BlockedCount(), 300);  // 0.25 * 1200
  auto b = RandomGrid(40, 30, 0.25, 7);
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(a->cells(), b->cells());
  auto c = RandomGrid(40, 30, 0.25, 8);
  ASSERT_TRUE(c.ok());
  EXPECT_NE(a->cells(), c->cells());
  EXPECT_EQ(c->BlockedCount(), 300);
}

TEST(GenerateTest, RandomGridSpreadsObstaclesOverTheGrid) {
  auto grid = RandomGrid(100, 100, 0.3, 1);
  ASSERT_TRUE(grid.ok());
  // Each quadrant holds close to 30% blocked cells (750 of 2500; binomial sd ~ 23).
  for (int qx = 0; qx < 2; ++qx) {
    for (int qy = 0; qy < 2; ++qy) {
      int blocked = 0;
      for (int y = qy * 50; y < qy * 50 + 50; ++y) {
        for (int x = qx * 50; x < qx * 50 + 50; ++x) blocked += grid->IsBlocked(x, y);
      }
      EXPECT_NEAR(blocked, 750, 120);
    }
  }
}

TEST(GenerateTest, RandomGridBlocksKeepFreeCellsAndExactCount) {
  RandomGridOptions options;
  options.width = 50;
  options.height = 40;
  options.obstacle_ratio = 0.4;
  options.block_size = 4;
  options.keep_free = {Cell{0, 0}, Cell{49, 39}, Cell{25, 20}};
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    auto grid = RandomGrid(options, seed);
    ASSERT_TRUE(grid.ok()) << grid.status();
    EXPECT_EQ(grid->BlockedCount(), 800);
    for (const Cell& c : options.keep_free) EXPECT_TRUE(grid->IsFree(c));
  }
  // Blocks make clusters: most blocked cells have a blocked 4-neighbour.
  auto grid = RandomGrid(options, 3);
  int clustered = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 50; ++x) {
      if (!grid->IsBlocked(x, y)) continue;
      clustered += (x > 0 && grid->IsBlocked(x - 1, y)) || (x < 49 && grid->IsBlocked(x + 1, y));
    }
  }
  EXPECT_GT(clustered, 700);
}

TEST(GenerateTest, RandomGridRejectsBadOptions) {
  EXPECT_EQ(RandomGrid(0, 5, 0.1, 1).status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(RandomGrid(5, 5, 1.0, 1).status().message(), HasSubstr("obstacle_ratio"));
  EXPECT_EQ(RandomGrid(100000, 100000, 0.1, 1).status().code(),
            absl::StatusCode::kResourceExhausted);
  RandomGridOptions options;
  options.width = 2;
  options.height = 2;
  options.obstacle_ratio = 0.9;
  options.keep_free = {Cell{0, 0}, Cell{1, 1}};
  EXPECT_THAT(RandomGrid(options, 1).status().message(), HasSubstr("only 2 may be blocked"));
  options.keep_free = {Cell{2, 0}};
  EXPECT_THAT(RandomGrid(options, 1).status().message(), HasSubstr("outside the grid"));
  options.keep_free.clear();
  options.block_size = 3;
  EXPECT_THAT(RandomGrid(options, 1).status().message(), HasSubstr("block_size"));
}

TEST(GenerateTest, RandomShapeWorldReachesTheTargetRatio) {
  RandomWorldOptions options;
  options.bounds = Bounds2{Point2(0, 0), Point2(100, 50)};
  options.obstacle_ratio = 0.3;
  options.min_radius = 1;
  options.max_radius = 3;
  options.keep_clear = {Point2(2, 2), Point2(98, 48)};
  options.keep_clear_radius = 1.5;
  auto world = RandomShapeWorld(options, 11);
  ASSERT_TRUE(world.ok()) << world.status();
  EXPECT_FALSE(world->circles().empty());
  EXPECT_FALSE(world->polygons().empty());
  // Overshoot is at most one obstacle: pi * 3^2 / 5000 < 0.006.
  const double share = CoveredShare(*world);
  EXPECT_GE(share, 0.3);
  EXPECT_LE(share, 0.3 + 0.006);
  for (const Circle& c : world->circles()) {
    for (const Point2& p : options.keep_clear) EXPECT_GT((c.center - p).norm(), c.radius + 1.5);
  }
  for (const Polygon& polygon : world->polygons()) {
    EXPECT_GE(polygon.vertices.size(), 3u);
    EXPECT_LE(polygon.vertices.size(), 8u);
    for (const Point2& v : polygon.vertices) {
      for (const Point2& p : options.keep_clear) EXPECT_GT((v - p).norm(), 1.5);
    }
  }
  auto again = RandomShapeWorld(options, 11);
  ASSERT_TRUE(again.ok());
  ASSERT_EQ(again->polygons().size(), world->polygons().size());
  ASSERT_EQ(again->circles().size(), world->circles().size());
  for (size_t i = 0; i < world->circles().size(); ++i) {
    EXPECT_EQ(again->circles()[i].center, world->circles()[i].center);
    EXPECT_EQ(again->circles()[i].radius, world->circles()[i].radius);
  }
}

TEST(GenerateTest, RandomShapeWorldCirclesOnly) {
  const Bounds2 bounds{Point2(-10, -10), Point2(10, 10)};
  auto world = RandomShapeWorld(bounds, 25, 0.5, 1.0, 3, {Point2(0, 0)}, 0.5);
  ASSERT_TRUE(world.ok()) << world.status();
  ASSERT_EQ(world->circles().size(), 25u);
  EXPECT_TRUE(world->polygons().empty());
  for (const Circle& c : world->circles()) {
    EXPECT_GE(c.radius, 0.5);
    EXPECT_LE(c.radius, 1.0);
    EXPECT_TRUE(bounds.Contains(c.center));
    EXPECT_GT(c.center.norm(), c.radius + 0.5);
  }
  auto zero = RandomShapeWorld(bounds, 0, 0.5, 1.0, 3);
  ASSERT_TRUE(zero.ok());
  EXPECT_EQ(zero->ObstacleCount(), 0u);
  EXPECT_EQ(CoveredShare(*zero), 0.0);
}

TEST(GenerateTest, RandomShapeWorldRejectsBadOptions) {
  const Bounds2 bounds{Point2(0, 0), Point2(10, 10)};
  EXPECT_THAT(RandomShapeWorld(bounds, 3, 2, 1, 1).status().message(), HasSubstr("radii"));
  EXPECT_THAT(RandomShapeWorld(Bounds2{}, 3, 1, 2, 1).status().message(), HasSubstr("bounds"));
  EXPECT_THAT(RandomShapeWorld(bounds, -1, 1, 2, 1).status().message(), HasSubstr("circles"));
  // A keep-clear zone covering the whole world leaves no room.
  EXPECT_THAT(RandomShapeWorld(bounds, 3, 1, 2, 1, {Point2(5, 5)}, 20).status().message(),
              HasSubstr("too little room"));
  RandomWorldOptions options;
  options.obstacle_ratio = 0.95;
  EXPECT_THAT(RandomShapeWorld(options, 1).status().message(), HasSubstr("obstacle_ratio"));
  options.obstacle_ratio = 0.2;
  options.min_vertices = 2;
  EXPECT_THAT(RandomShapeWorld(options, 1).status().message(), HasSubstr("vertices"));
}

TEST(GenerateTest, CoveredShareOfKnownShapes) {
  auto world =
      ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(10, 10)}, {Circle{Point2(5, 5), 2}},
                         {Polygon{{Point2(0, 0), Point2(10, 0), Point2(10, 1), Point2(0, 1)}}});
  ASSERT_TRUE(world.ok());
  // Circle 4 pi / 100 = 0.1257 plus the strip 0.1.
  EXPECT_NEAR(CoveredShare(*world, 512), 0.1 + 0.04 * M_PI, 0.003);
}

}  // namespace
}  // namespace swarmplan
