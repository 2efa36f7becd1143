#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bench/papers/bas_canyon_terrain.h"
#include "core/algorithms/exact/terrain_lattice.h"
#include "core/map/io/map_io.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

double HeightAt(const CanyonShape& shape, const std::vector<double>& heights, int x, int y) {
  return heights[static_cast<size_t>(y) * shape.width + x];
}

TEST(BasCanyonTest, SameSeedSameHeightsOtherSeedOtherRocks) {
  const CanyonShape shape;
  EXPECT_EQ(CanyonHeights(shape, 7), CanyonHeights(shape, 7));
  EXPECT_NE(CanyonHeights(shape, 7), CanyonHeights(shape, 8));
}

TEST(BasCanyonTest, WithoutRocksTheValleyFloorFollowsTheRightBranch) {
  CanyonShape shape;
  shape.rocks = 0;
  const std::vector<double> heights = CanyonHeights(shape, 1);
  ASSERT_EQ(heights.size(), static_cast<size_t>(shape.width * shape.depth));
  // The mouth at the start's column: the right branch's floor exactly.
  EXPECT_DOUBLE_EQ(HeightAt(shape, heights, 0, static_cast<int>(shape.mouth_y)), shape.right_floor);
  for (int x = 0; x < shape.width; ++x) {
    const int floor_y = static_cast<int>(std::lround(RightBranchY(shape, x)));
    const double floor = HeightAt(shape, heights, x, floor_y);
    EXPECT_LE(floor, shape.right_floor + 1.0) << "column " << x;
    // Every cell of the column is at least as high as the floor (up to the rounding of y).
    for (int y = 0; y < shape.depth; ++y) {
      EXPECT_GE(HeightAt(shape, heights, x, y), shape.right_floor - 1e-9);
      EXPECT_LE(HeightAt(shape, heights, x, y), shape.plateau + 1e-9);
    }
  }
}

TEST(BasCanyonTest, RightBranchBulgesToTheRightAndJoinsTheMouthAtBothEnds) {
  const CanyonShape shape;
  EXPECT_NEAR(RightBranchY(shape, 0), shape.mouth_y, 1e-12);
  EXPECT_NEAR(RightBranchY(shape, shape.width - 1), shape.mouth_y, 1e-12);
  EXPECT_GT(RightBranchY(shape, (shape.width - 1) / 2.0), shape.mouth_y);
  EXPECT_NEAR(LeftBranchY(shape, shape.width - 1), shape.mouth_y, 1e-12);
  EXPECT_LT(LeftBranchY(shape, (shape.width - 1) / 2.0), shape.mouth_y);
}

TEST(BasCanyonTest, AscTextLoadsAsTheSameTerrain) {
  const CanyonShape shape;
  const std::vector<double> heights = CanyonHeights(shape, 2020);
  const std::string text = HeightsToAsc(shape.width, shape.depth, heights);
  absl::StatusOr<Map> map = ParseMap("terrain-asc", {{"canyon.asc", text}});
  ASSERT_TRUE(map.ok()) << map.status();
  const Terrain* terrain = map->terrain();
  ASSERT_NE(terrain, nullptr);
  ASSERT_EQ(terrain->width(), shape.width);
  ASSERT_EQ(terrain->depth(), shape.depth);
  for (int y = 0; y < shape.depth; ++y) {
    for (int x = 0; x < shape.width; ++x) {
      EXPECT_DOUBLE_EQ(terrain->HeightAt(x, y), HeightAt(shape, heights, x, y));
    }
  }
}

TEST(BasCanyonTest, AscTextHasTheHeaderAndTheNorthernRowFirst) {
  const std::string text = HeightsToAsc(2, 2, {1.0, 2.0, 3.0, 4.5});
  EXPECT_EQ(text,
            "ncols 2\nnrows 2\nxllcenter 0\nyllcenter 0\ncellsize 1\n"
            "3.00 4.50\n1.00 2.00\n");
}

// The yardstick of the reproduction: on the canyon (world = cell coordinates), the lattice
// optimum from mouth to mouth is collision-free and follows the deep right valley.
TEST(BasCanyonTest, LatticeYardstickFollowsTheDeepRightValley) {
  const CanyonShape shape;
  absl::StatusOr<Map> map = ParseMap(
      "terrain-asc",
      {{"canyon.asc", HeightsToAsc(shape.width, shape.depth, CanyonHeights(shape, 2020))}});
  ASSERT_TRUE(map.ok()) << map.status();
  const Terrain& terrain = *map->terrain();
  const Point2 s(0, shape.mouth_y), g(shape.width - 1, shape.mouth_y);
  const Point3 start(s.x(), s.y(), terrain.GroundAt(s) + 1);
  const Point3 goal(g.x(), g.y(), terrain.GroundAt(g) + 1);
  TerrainLatticeOptions options;
  options.vertical_step = 1.0;
  absl::StatusOr<TerrainLatticeResult> lattice =
      TerrainLatticeOptimum(terrain, start, goal, 0.0, options);
  ASSERT_TRUE(lattice.ok()) << lattice.status();
  ASSERT_FALSE(lattice->path.empty());
  EXPECT_EQ(lattice->path.front(), start);
  EXPECT_EQ(lattice->path.back(), goal);
  EXPECT_TRUE(EvaluatePath(*map, lattice->path, 0.0).collision_free);
  double deepest_y = 0.0;
  for (const Point3& p : lattice->path) {
    if (std::abs(p.x() - (shape.width - 1) / 2.0) <= 0.5) deepest_y = std::max(deepest_y, p.y());
  }
  EXPECT_GT(deepest_y, shape.mouth_y);
}

}  // namespace
}  // namespace swarmplan::bench
