// Maps whose coordinates or extents leave +-kMaxWorldCoordinate are refused with an error that
// names the field (their distance fields would overflow float, their squared lengths double).

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/map/limits.h"
#include "core/map/occupancy_grid.h"
#include "core/map/shape_world.h"
#include "core/map/terrain.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

TEST(WorldRangeTest, ShapeWorldsBeyondTheRangeAreRefused) {
  // Found by fuzz_request: bounds 8e265 wide with an edge longer than sqrt(DBL_MAX).
  absl::StatusOr<ShapeWorld> huge =
      ShapeWorld::Create({{0, 0}, {8.06e265, 235.0}}, {{{5, 5}, 1.0}},
                         {Polygon{{{1, 1.00003}, {3, 1}, {1.36e-312, 5.96e251}}}});
  ASSERT_FALSE(huge.ok());
  EXPECT_THAT(huge.status().message(), HasSubstr("bounds"));
  const double big = 0.9 * std::numeric_limits<double>::max();
  EXPECT_FALSE(ShapeWorld::Create({{-big, 0}, {big, 1}}, {}, {}).ok());
  absl::StatusOr<ShapeWorld> circle = ShapeWorld::Create({{0, 0}, {10, 10}}, {{{5, 5}, 1e13}}, {});
  ASSERT_FALSE(circle.ok());
  EXPECT_THAT(circle.status().message(), HasSubstr("circles[0]"));
  absl::StatusOr<ShapeWorld> vertex =
      ShapeWorld::Create({{0, 0}, {10, 10}}, {}, {Polygon{{{1, 1}, {2e12, 1}, {1, 2}}}});
  ASSERT_FALSE(vertex.ok());
  EXPECT_THAT(vertex.status().message(), HasSubstr("polygons[0]"));
  // At the edge of the range a world is still a world.
  EXPECT_TRUE(ShapeWorld::Create({{-kMaxWorldCoordinate, 0}, {kMaxWorldCoordinate, 1e6}},
                                 {{{0, 5e5}, 1e5}}, {})
                  .ok());
}

TEST(WorldRangeTest, GridsAndTerrainsBeyondTheRangeAreRefused) {
  const std::vector<int8_t> cells(4, 0);
  absl::StatusOr<OccupancyGrid> far = OccupancyGrid::Create(2, 2, cells, 1.0, {2e12, 0});
  ASSERT_FALSE(far.ok());
  EXPECT_THAT(far.status().message(), HasSubstr("origin"));
  absl::StatusOr<OccupancyGrid> wide = OccupancyGrid::Create(2, 2, cells, 1e300, {0, 0});
  ASSERT_FALSE(wide.ok());
  EXPECT_THAT(wide.status().message(), HasSubstr("resolution"));
  EXPECT_TRUE(OccupancyGrid::Create(2, 2, cells, 1e6, {-1e9, 1e9}).ok());

  const std::vector<double> heights(4, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  absl::StatusOr<Terrain> cell = Terrain::Create(2, 2, heights, 1e300, {0, 0}, nan);
  ASSERT_FALSE(cell.ok());
  EXPECT_THAT(cell.status().message(), HasSubstr("cell size"));
  absl::StatusOr<Terrain> high = Terrain::Create(2, 2, {1, 2, 3, 1e200}, 1.0, {0, 0}, nan);
  ASSERT_FALSE(high.ok());
  EXPECT_THAT(high.status().message(), HasSubstr("height at 1,1"));
  EXPECT_TRUE(Terrain::Create(2, 2, heights, 10.0, {5e5, 4e6}, nan).ok());
}

}  // namespace
}  // namespace swarmplan
