#include <algorithm>
#include <cmath>

#include "core/grid_ops/cell_path.h"
#include "core/grid_ops/collinear.h"
#include "core/grid_ops/grid_moves.h"
#include "core/grid_ops/grid_space.h"
#include "core/grid_ops/roulette.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"
#include "tests/unit/seed_test_maps.h"

namespace swarmplan {
namespace {

using testing::GridFromRows;

bool Contains(const std::vector<Cell>& cells, Cell c) {
  return std::find(cells.begin(), cells.end(), c) != cells.end();
}

TEST(GridOpsTest, MoveOffsetsHaveTheRightSizes) {
  EXPECT_EQ(MoveOffsets(Neighbourhood::k4).size(), 4u);
  EXPECT_EQ(MoveOffsets(Neighbourhood::k8).size(), 8u);
  EXPECT_EQ(MoveOffsets(Neighbourhood::k24).size(), 24u);
}

TEST(GridOpsTest, SegmentTouchesCornersOfADiagonal) {
  const std::vector<Cell> touched = CellsTouchedBySegment(Cell{0, 0}, Cell{1, 1});
  EXPECT_EQ(touched.size(), 4u);  // both ends and the two cells whose corner it grazes
  EXPECT_TRUE(Contains(touched, Cell{1, 0}));
  EXPECT_TRUE(Contains(touched, Cell{0, 1}));
}

TEST(GridOpsTest, SegmentOfAKnightMoveTouchesFourCells) {
  const std::vector<Cell> touched = CellsTouchedBySegment(Cell{0, 0}, Cell{2, 1});
  EXPECT_EQ(touched.size(), 4u);
  EXPECT_TRUE(Contains(touched, Cell{1, 0}));
  EXPECT_TRUE(Contains(touched, Cell{1, 1}));
  EXPECT_FALSE(Contains(touched, Cell{0, 1}));
  EXPECT_FALSE(Contains(touched, Cell{2, 0}));
}

TEST(GridOpsTest, SegmentBoxDistance) {
  EXPECT_DOUBLE_EQ(SegmentBoxDistance({0, 0}, {4, 0}, {1, -1}, {2, 1}), 0.0);
  EXPECT_DOUBLE_EQ(SegmentBoxDistance({0, 0}, {4, 0}, {1, 1}, {2, 2}), 1.0);
  EXPECT_NEAR(SegmentBoxDistance({0, 0}, {0, 4}, {1, 5}, {2, 6}), std::sqrt(2.0), 1e-12);
}

TEST(GridOpsTest, DiagonalPastABlockedCornerIsNotAMove) {
  const OccupancyGrid grid = GridFromRows({"..", "#."});
  GridMoves checked(grid, MoveRules{Neighbourhood::k8, true, 0.0});
  EXPECT_FALSE(checked.IsMove(Cell{0, 0}, Cell{1, 1}));
  EXPECT_TRUE(checked.IsMove(Cell{0, 0}, Cell{1, 0}));
  GridMoves jumping(grid, MoveRules{Neighbourhood::k8, false, 0.0});
  EXPECT_TRUE(jumping.IsMove(Cell{0, 0}, Cell{1, 1}));
}

TEST(GridOpsTest, LongMovesAreSegmentChecked) {
  const OccupancyGrid grid = GridFromRows({"...", ".#.", "..."});
  GridMoves moves(grid, MoveRules{Neighbourhood::k24, true, 0.0});
  EXPECT_FALSE(moves.IsMove(Cell{0, 0}, Cell{2, 2}));  // through the blocked centre
  EXPECT_FALSE(moves.IsMove(Cell{0, 0}, Cell{2, 1}));  // cuts the blocked square
  EXPECT_TRUE(moves.IsMove(Cell{0, 0}, Cell{2, 0}));   // along the free row
  EXPECT_FALSE(moves.IsMove(Cell{0, 0}, Cell{0, 3}));  // outside the grid
  const std::vector<Cell>& from_corner = moves.ValidMoves(Cell{0, 0});
  EXPECT_TRUE(Contains(from_corner, Cell{2, 0}));
  EXPECT_FALSE(Contains(from_corner, Cell{1, 1}));
  EXPECT_EQ(moves.cells_computed(), 1);
  moves.ValidMoves(Cell{0, 0});
  EXPECT_EQ(moves.cells_computed(), 1);  // shared, not recomputed
  GridMoves jumping(grid, MoveRules{Neighbourhood::k24, false, 0.0});
  EXPECT_TRUE(jumping.IsMove(Cell{0, 0}, Cell{2, 2}));
}

TEST(GridOpsTest, LongMovesKeepClearance) {
  const OccupancyGrid grid = GridFromRows({".....", ".....", "..#..", ".....", "....."});
  GridMoves moves(grid, MoveRules{Neighbourhood::k24, true, 0.7});
  // From (0,1) to (2,0): the segment passes 0.447 from the blocked square's corner (2,2)...
  EXPECT_TRUE(moves.Usable(Cell{0, 0}));
  EXPECT_FALSE(moves.Usable(Cell{2, 1}));  // centre 0.5 from the blocked square
  EXPECT_FALSE(moves.StepValid(Cell{1, 0}, Cell{3, 1}) && moves.Usable(Cell{3, 1}));
}

TEST(GridOpsTest, RemoveLoopsCutsRevisits) {
  std::vector<Cell> path{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0}, {1, -1}, {2, -1}};
  RemoveLoops(path);
  const std::vector<Cell> want{{0, 0}, {1, 0}, {1, -1}, {2, -1}};
  EXPECT_EQ(path, want);
  std::vector<Cell> nested{{0, 0}, {1, 0}, {2, 0}, {1, 0}, {0, 0}, {0, 1}};
  RemoveLoops(nested);
  const std::vector<Cell> want_nested{{0, 0}, {0, 1}};
  EXPECT_EQ(nested, want_nested);
  std::vector<Cell> clean{{0, 0}, {1, 1}};
  RemoveLoops(clean);
  EXPECT_EQ(clean.size(), 2u);
}

TEST(GridOpsTest, RepairGapsJoinsAroundAWall) {
  const OccupancyGrid grid = GridFromRows({
      ".....",  //
      "..#..",  //
      "..#..",  //
      ".....",  //
  });
  GridMoves moves(grid, MoveRules{Neighbourhood::k8, true, 0.0});
  std::vector<Cell> path{{0, 1}, {1, 1}, {3, 1}, {4, 1}};
  ASSERT_TRUE(RepairGaps(moves, path, nullptr));
  EXPECT_TRUE(IsValidCellPath(moves, path));
  EXPECT_EQ(path.front(), (Cell{0, 1}));
  EXPECT_EQ(path.back(), (Cell{4, 1}));
  // Over the top of the wall; no diagonal may graze the wall, so every step is orthogonal.
  EXPECT_TRUE(Contains(path, Cell{2, 0}));
  EXPECT_NEAR(CellPathLength(grid, path), 6.0, 1e-9);
}

TEST(GridOpsTest, RepairGapsFailsAcrossASolidWallAndLeavesThePath) {
  const OccupancyGrid grid = GridFromRows({"..#..", "..#..", "..#.."});
  GridMoves moves(grid, MoveRules{Neighbourhood::k8, true, 0.0});
  std::vector<Cell> path{{0, 0}, {1, 0}, {3, 0}};
  const std::vector<Cell> before = path;
  EXPECT_FALSE(RepairGaps(moves, path, nullptr));
  EXPECT_EQ(path, before);
}

TEST(GridOpsTest, RepairGapsRespectsFourConnectivity) {
  const OccupancyGrid grid = GridFromRows({"...", "...", "..."});
  GridMoves moves(grid, MoveRules{Neighbourhood::k4, true, 0.0});
  std::vector<Cell> path{{0, 0}, {2, 2}};
  ASSERT_TRUE(RepairGaps(moves, path, nullptr));
  EXPECT_EQ(path.size(), 5u);
  EXPECT_TRUE(IsValidCellPath(moves, path));
}

TEST(GridOpsTest, RandomFeasiblePathIsConnectedAndReproducible) {
  const OccupancyGrid grid = GridFromRows(testing::TwoWallsRows());
  GridMoves moves(grid, MoveRules{Neighbourhood::k8, true, 0.0});
  const std::vector<Cell> reachable = ReachableCells(moves, Cell{0, 0});
  EXPECT_EQ(reachable.size(), static_cast<size_t>(144 - 12));
  Rng a(3), b(3);
  for (int i = 0; i < 20; ++i) {
    auto pa = RandomFeasiblePath(moves, Cell{0, 0}, Cell{11, 11}, reachable, 3, a, nullptr);
    auto pb = RandomFeasiblePath(moves, Cell{0, 0}, Cell{11, 11}, reachable, 3, b, nullptr);
    ASSERT_TRUE(pa.has_value());
    EXPECT_TRUE(IsValidCellPath(moves, *pa));
    EXPECT_EQ(pa->front(), (Cell{0, 0}));
    EXPECT_EQ(pa->back(), (Cell{11, 11}));
    EXPECT_EQ(*pa, *pb);
  }
}

TEST(GridOpsTest, RouletteFollowsTheWeights) {
  Rng rng(11);
  std::vector<int> counts(3, 0);
  for (int i = 0; i < 30000; ++i) ++counts[RouletteSelect({1.0, 0.0, 3.0}, rng)];
  EXPECT_EQ(counts[1], 0);
  EXPECT_NEAR(counts[2] / 30000.0, 0.75, 0.02);
  EXPECT_EQ(RouletteSelect({}, rng), -1);
  const int any = RouletteSelect({0.0, 0.0}, rng);
  EXPECT_TRUE(any == 0 || any == 1);
}

TEST(GridOpsTest, PruneCollinearKeepsOnlyCorners) {
  const Path path{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 0, 0}, {3, 1, 0}, {4, 2, 0}, {4, 3, 0}};
  const Path pruned = PruneCollinear(path);
  const Path want{{0, 0, 0}, {2, 0, 0}, {4, 2, 0}, {4, 3, 0}};
  EXPECT_EQ(pruned, want);
}

// The ends of a grid path: the end cell's centre is replaced by the exact point when the
// segment to the next centre keeps the clearance, and the point is joined to it otherwise; the
// length is that of the world path.
TEST(GridSpaceTest, EndsReplacedWhenFreeAndJoinedOtherwise) {
  // Row 0 free; (1, 1) blocked, so the centre (1.5, 0.5) keeps 0.5 from it.
  const MapPtr map = testing::GridMap({"...", ".#."});
  Problem problem;
  problem.map = map;
  problem.clearance = 0.45;
  problem.goal = Point3(2.5, 0.5, 0);
  const std::vector<Cell> cells = {Cell{0, 0}, Cell{1, 0}, Cell{2, 0}};

  problem.start = Point3(0.2, 0.3, 0);  // the segment to (1.5, 0.5) keeps the clearance
  absl::StatusOr<GridSpace> space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok()) << space.status();
  Path path = space->WorldPath(cells);
  EXPECT_EQ(path, (Path{problem.start, Point3(1.5, 0.5, 0), problem.goal}));
  EXPECT_TRUE(space->PathFree(path));
  EXPECT_NEAR(space->PathLength(cells), PathLength(path), 1e-12);

  problem.start = Point3(0.2, 0.95, 0);  // it would pass 0.31 from the corner (1, 1)
  space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok()) << space.status();
  path = space->WorldPath(cells);
  EXPECT_EQ(path, (Path{problem.start, Point3(0.5, 0.5, 0), Point3(1.5, 0.5, 0), problem.goal}));
  EXPECT_TRUE(space->PathFree(path));
  EXPECT_NEAR(space->PathLength(cells), PathLength(path), 1e-12);

  // Start and goal in one cell: the segment between them.
  problem.goal = Point3(0.4, 0.6, 0);
  space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok()) << space.status();
  EXPECT_EQ(space->WorldPath({Cell{0, 0}}), (Path{problem.start, problem.goal}));
  EXPECT_NEAR(space->PathLength({Cell{0, 0}}), (problem.goal - problem.start).norm(), 1e-12);
}

// Validating a request builds the space: its raster's distance field waits for a planner that
// needs it.
TEST(GridSpaceTest, RasterOfAShapeWorldComputesNoDistanceFieldForItsEnds) {
  Problem problem = seed_testing::MakeProblem(seed_testing::BlockWorld(), {5, 5}, {35, 25}, 1.0);
  absl::StatusOr<GridSpace> space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok()) << space.status();
  EXPECT_FALSE(space->grid->distance_field_computed());

  problem.start = Point3(9.5, 15, 0);  // 0.5 from the block: its cell is not usable
  space = MakeGridSpace(problem, 0.0);
  ASSERT_FALSE(space.ok());
  EXPECT_TRUE(absl::IsFailedPrecondition(space.status())) << space.status();
}

}  // namespace
}  // namespace swarmplan
