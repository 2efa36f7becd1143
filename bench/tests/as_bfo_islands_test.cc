#include <cmath>
#include <vector>

#include "bench/papers/as_bfo_islands_check.h"
#include "bench/papers/as_bfo_islands_world.h"
#include "core/graph/grid_search.h"
#include "core/map/io/map_writers.h"
#include "core/map/map.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

OccupancyGrid MakeGrid(const std::vector<std::string>& rows) {
  std::vector<int8_t> cells;
  for (const std::string& row : rows) {
    for (char c : row) cells.push_back(c == '#' ? OccupancyGrid::kOccupied : OccupancyGrid::kFree);
  }
  return *OccupancyGrid::Create(static_cast<int>(rows.front().size()),
                                static_cast<int>(rows.size()), std::move(cells));
}

Path CellsToPath(const OccupancyGrid& grid, const std::vector<Cell>& cells) {
  return CellPathToWorld(grid, cells);
}

// Checks a path of cells as the experiment does, with the metrics computed for it.
absl::Status Check(const OccupancyGrid& grid, const std::vector<Cell>& cells, double optimum) {
  const Map map(grid);
  const Path path = CellsToPath(grid, cells);
  return CheckGridPath(grid, path, EvaluatePath(map, path, 0.0), Cell{0, 0},
                       Cell{grid.width() - 1, grid.height() - 1}, optimum);
}

TEST(AsBfoIslandsWorldTest, EverySizeHasTheSameObstacleRatioAndConnectedCorners) {
  for (const IslandEnvironmentSpec& spec : AsBfoEnvironments()) {
    absl::StatusOr<IslandLayout> layout = AcceptedIslands(spec, AsBfoSizes());
    ASSERT_TRUE(layout.ok()) << layout.status();
    for (int n : AsBfoSizes()) {
      absl::StatusOr<OccupancyGrid> grid = RasteriseIslands(layout->discs, n, spec.obstacle_ratio);
      ASSERT_TRUE(grid.ok()) << grid.status();
      EXPECT_EQ(grid->BlockedCount(), std::lround(spec.obstacle_ratio * n * n)) << spec.name << n;
      EXPECT_TRUE(grid->IsFree(IslandStart(n)));
      EXPECT_TRUE(grid->IsFree(IslandGoal(n)));
      const GridSearchResult path = SearchGrid(*grid, IslandStart(n), IslandGoal(n));
      ASSERT_TRUE(path.found) << spec.name << " " << n;
      EXPECT_GT(path.length, (n - 1) * std::sqrt(2.0)) << "the diagonal is open";
      // Island-like: a few blobs, not scattered cells.
      EXPECT_LE(CountIslands(*grid), spec.islands + 3) << spec.name << " " << n;
    }
  }
}

TEST(AsBfoIslandsWorldTest, SameSeedSameIslands) {
  const IslandEnvironmentSpec& spec = AsBfoEnvironments().front();
  const std::vector<IslandDisc> a = DrawIslands(spec, 7);
  const std::vector<IslandDisc> b = DrawIslands(spec, 7);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].centre, b[i].centre);
    EXPECT_EQ(a[i].radius, b[i].radius);
  }
  EXPECT_NE(DrawIslands(spec, 8).front().centre, a.front().centre);
}

TEST(AsBfoIslandsWorldTest, RasterBlocksTheDeepestCellsOfADisc) {
  const std::vector<IslandDisc> disc{{Point2(0.5, 0.5), 0.2}};
  absl::StatusOr<OccupancyGrid> grid = RasteriseIslands(disc, 10, 0.04);
  ASSERT_TRUE(grid.ok()) << grid.status();
  EXPECT_EQ(grid->BlockedCount(), 4);
  for (Cell c : {Cell{4, 4}, Cell{5, 4}, Cell{4, 5}, Cell{5, 5}}) EXPECT_TRUE(grid->IsBlocked(c));
  EXPECT_EQ(CountIslands(*grid), 1);
  EXPECT_EQ(FormatAsciiMap(MakeGrid({"#.", ".#"})), "#.\n.#\n");
  EXPECT_FALSE(RasteriseIslands(disc, 1, 0.2).ok());
  EXPECT_FALSE(RasteriseIslands(disc, 10, 1.0).ok());
}

TEST(AsBfoIslandsWorldTest, CountsDiagonallyTouchingCellsAsOneIsland) {
  EXPECT_EQ(CountIslands(MakeGrid({"#...", ".#..", "...#", "...#"})), 2);
  EXPECT_EQ(CountIslands(MakeGrid({"....", "...."})), 0);
}

TEST(AsBfoIslandsCheckTest, AcceptsAnOptimalPathAndPrunedStraightRuns) {
  const OccupancyGrid grid = MakeGrid({"....", ".##.", "....", "...."});
  const GridSearchResult best = SearchGrid(grid, Cell{0, 0}, Cell{3, 3});
  ASSERT_TRUE(best.found);
  EXPECT_TRUE(Check(grid, best.cells, best.length).ok());
  // The same kind of path with straight runs merged into one segment.
  EXPECT_TRUE(Check(grid, {{0, 0}, {0, 2}, {1, 3}, {3, 3}}, best.length).ok());
}

TEST(AsBfoIslandsCheckTest, RejectsGapsCornerCutsWrongEndsAndTooShortPaths) {
  const OccupancyGrid grid = MakeGrid({"....", ".##.", "....", "...."});
  const double optimum = SearchGrid(grid, Cell{0, 0}, Cell{3, 3}).length;
  // A knight's move is no grid direction.
  EXPECT_FALSE(Check(grid, {{0, 0}, {0, 1}, {1, 3}, {2, 3}, {3, 3}}, optimum).ok());
  // Through an obstacle.
  EXPECT_FALSE(Check(grid, {{0, 0}, {1, 1}, {2, 2}, {3, 3}}, optimum).ok());
  // Cutting the corner of (1, 1): (0, 1) -> (1, 2) passes between (0, 2) and (1, 1).
  EXPECT_FALSE(Check(grid, {{0, 0}, {0, 1}, {1, 2}, {2, 3}, {3, 3}}, optimum).ok());
  // Wrong start and wrong goal.
  EXPECT_FALSE(Check(grid, {{1, 0}, {2, 0}, {3, 1}, {3, 2}, {3, 3}}, optimum).ok());
  EXPECT_FALSE(Check(grid, {{0, 0}, {0, 1}, {0, 2}, {1, 3}, {2, 3}}, optimum).ok());
  // Shorter than the claimed optimum.
  EXPECT_FALSE(Check(grid, {{0, 0}, {0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 3}}, optimum + 1).ok());
  // Not at cell centres.
  const Map map(grid);
  Path off = CellsToPath(grid, {{0, 0}, {0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 3}});
  off[2].x() += 0.25;
  EXPECT_FALSE(
      CheckGridPath(grid, off, EvaluatePath(map, off, 0.0), Cell{0, 0}, Cell{3, 3}, optimum).ok());
  EXPECT_FALSE(CheckGridPath(grid, {}, PathMetrics{}, Cell{0, 0}, Cell{3, 3}, optimum).ok());
}

}  // namespace
}  // namespace swarmplan::bench
