#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "core/graph/visibility_graph.h"
#include "core/map/map.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

Map BlockAndDiscWorld() {
  const Polygon block{{Point2(4, -3), Point2(6, -3), Point2(6, 3), Point2(4, 3)}};
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(Bounds2{Point2(0, -5), Point2(10, 5)},
                                                        {Circle{Point2(8, 1), 0.7}}, {block});
  EXPECT_TRUE(world.ok()) << world.status();
  return Map(Map::Data(*std::move(world)));
}

TEST(VisibilityGraphCacheTest, MapVariantCachesGrownObstaclesPerClearanceAndTolerance) {
  const Map map = BlockAndDiscWorld();
  const Point2 start(1, 0), goal(9.5, -1);
  for (const double clearance : {0.0, 0.3}) {
    absl::StatusOr<Path> direct =
        ShortestPathVisibility(*map.world(), start, goal, clearance, 0.01);
    ASSERT_TRUE(direct.ok()) << direct.status();
    const int64_t builds_before = map.derived_cache().builds();
    for (int repeat = 0; repeat < 3; ++repeat) {
      absl::StatusOr<Path> cached = ShortestPathVisibility(map, start, goal, clearance, 0.01);
      ASSERT_TRUE(cached.ok()) << cached.status();
      EXPECT_EQ(*cached, *direct);
    }
    EXPECT_EQ(map.derived_cache().builds(), builds_before + 1);
  }
  // Another tolerance is another entry.
  ASSERT_TRUE(ShortestPathVisibility(map, start, goal, 0.3, 0.05).ok());
  EXPECT_EQ(map.derived_cache().size(), 3u);
}

TEST(VisibilityGraphCacheTest, MapVariantKeepsTheErrors) {
  const Map map = BlockAndDiscWorld();
  EXPECT_EQ(ShortestPathVisibility(map, Point2(5, 0), Point2(9, 4), 0.0, 0.01).status().code(),
            absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(ShortestPathVisibility(map, Point2(1, 0), Point2(9, 4), -1.0, 0.01).status().code(),
            absl::StatusCode::kInvalidArgument);
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(2, 2, std::vector<int8_t>(4, 0));
  ASSERT_TRUE(grid.ok());
  const Map grid_map(Map::Data(*std::move(grid)));
  EXPECT_EQ(
      ShortestPathVisibility(grid_map, Point2(0.5, 0.5), Point2(1, 1), 0.0, 0.01).status().code(),
      absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace swarmplan
