#include <cmath>
#include <string>
#include <vector>

#include "bench/papers/bas_canyon_lattice.h"
#include "bench/papers/bas_canyon_terrain.h"
#include "core/algorithms/bas/terrain_objective.h"
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

Problem TerrainProblem(int width, int depth, std::vector<double> heights, const Point3& start,
                       const Point3& goal) {
  // Cell centres at integers, as in the canyon's file.
  absl::StatusOr<Terrain> terrain =
      Terrain::Create(width, depth, std::move(heights), 1.0, Point2(-0.5, -0.5));
  EXPECT_TRUE(terrain.ok()) << terrain.status();
  Problem problem;
  problem.map = std::make_shared<const Map>(std::move(*terrain));
  problem.start = start;
  problem.goal = goal;
  return problem;
}

TEST(BasCanyonLatticeTest, FlatGroundPathDropsToTheGroundBetweenStartAndGoal) {
  // Ground 0 everywhere (ceiling 1): from (0, 2, 1) to (4, 2, 1) the best path drops to the
  // ground at once and climbs at the last step: lengths sqrt(2) + 1 + 1 + sqrt(2), heights
  // 0 + 0 + 0 + 1.
  const Problem problem =
      TerrainProblem(5, 5, std::vector<double>(25, 0.0), Point3(0, 2, 1), Point3(4, 2, 1));
  absl::StatusOr<LatticePath> lattice = LatticeOptimum(problem);
  ASSERT_TRUE(lattice.ok()) << lattice.status();
  EXPECT_NEAR(lattice->fitness, 2 * std::sqrt(2.0) + 2 + 1, 1e-12);
  ASSERT_EQ(lattice->path.size(), 5u);
  for (int c = 1; c <= 3; ++c) {
    EXPECT_EQ(lattice->path[c], Point3(c, 2, 0)) << "waypoint " << c;
  }
}

TEST(BasCanyonLatticeTest, PathGoesThroughTheGapOfAWall) {
  // A wall of height 5 across column 3 with one gap (height 0) at row 6.
  const int width = 7, depth = 9;
  std::vector<double> heights(width * depth, 0.0);
  for (int y = 0; y < depth; ++y) heights[y * width + 3] = y == 6 ? 0.0 : 5.0;
  const Problem problem = TerrainProblem(width, depth, heights, Point3(0, 2, 1), Point3(6, 2, 1));
  absl::StatusOr<LatticePath> lattice = LatticeOptimum(problem);
  ASSERT_TRUE(lattice.ok()) << lattice.status();
  EXPECT_TRUE(EvaluatePath(*problem.map, lattice->path, 0.0).collision_free);
  // Flying over the wall costs at least 5 per waypoint near it; the gap is cheaper.
  EXPECT_NEAR(lattice->path[3].y(), 6.0, 0.5);
}

TEST(BasCanyonLatticeTest, FitnessIsThePlannersFitnessOfItsPath) {
  const CanyonShape shape;
  const std::vector<double> heights = CanyonHeights(shape, 2020);
  const Point3 start(0, 10, heights[10 * shape.width] + 1);
  const Point3 goal(20, 10, heights[10 * shape.width + 20] + 1);
  const Problem problem = TerrainProblem(shape.width, shape.depth, heights, start, goal);
  LatticeOptions options;
  options.y_step = 1.0;
  options.z_step = 0.5;
  absl::StatusOr<LatticePath> lattice = LatticeOptimum(problem, options);
  ASSERT_TRUE(lattice.ok()) << lattice.status();
  absl::StatusOr<std::unique_ptr<TerrainObjective>> objective =
      TerrainObjective::Create(problem, 100.0);
  ASSERT_TRUE(objective.ok()) << objective.status();
  Eigen::VectorXd x(2 * (lattice->path.size() - 2));
  for (size_t k = 1; k + 1 < lattice->path.size(); ++k) {
    x[2 * (k - 1)] = lattice->path[k].y();
    x[2 * (k - 1) + 1] = lattice->path[k].z();
  }
  const Evaluation evaluation = (*objective)->Evaluate(x);
  EXPECT_TRUE(evaluation.feasible);
  EXPECT_NEAR(evaluation.fitness, lattice->fitness, 1e-9);
  EXPECT_TRUE(EvaluatePath(*problem.map, lattice->path, 0.0).collision_free);
  // The optimum follows the deep right valley.
  EXPECT_GT(lattice->path[10].y(), shape.mouth_y);
}

}  // namespace
}  // namespace swarmplan::bench
