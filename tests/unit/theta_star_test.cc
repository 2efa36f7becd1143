#include "core/graph/theta_star.h"

#include <cmath>
#include <string>
#include <vector>

#include "absl/strings/str_join.h"
#include "core/geometry/grid_collision.h"
#include "core/graph/grid_search.h"
#include "core/map/io/map_io.h"
#include "core/path_metrics.h"
#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

OccupancyGrid AsciiGrid(const std::vector<std::string>& rows) {
  absl::StatusOr<Map> map = ParseMap("ascii", {{"test.txt", absl::StrJoin(rows, "\n")}});
  EXPECT_TRUE(map.ok()) << map.status();
  return *map->grid();
}

OccupancyGrid RandomGrid(int width, int height, double blocked_ratio, uint64_t seed) {
  Rng rng(seed);
  std::vector<int8_t> cells(static_cast<size_t>(width) * height);
  for (int8_t& c : cells) c = rng.Bernoulli(blocked_ratio) ? OccupancyGrid::kOccupied : 0;
  return *OccupancyGrid::Create(width, height, std::move(cells));
}

Cell RandomFreeCell(const OccupancyGrid& grid, Rng& rng) {
  while (true) {
    const Cell c{static_cast<int>(rng.UniformInt(0, grid.width() - 1)),
                 static_cast<int>(rng.UniformInt(0, grid.height() - 1))};
    if (grid.IsFree(c)) return c;
  }
}

double StraightLine(const OccupancyGrid& grid, Cell a, Cell b) {
  return (grid.CellCenter(a) - grid.CellCenter(b)).norm();
}

TEST(ThetaStarTest, StraightLineInTheOpen) {
  const OccupancyGrid grid = AsciiGrid({"..........", "..........", "..........", ".........."});
  const GridCollisionChecker checker(grid);
  const GridSearchResult r = ThetaStar(grid, checker, {0, 0}, {9, 3});
  ASSERT_TRUE(r.found);
  ASSERT_EQ(r.cells.size(), 2u);
  EXPECT_NEAR(r.length, std::hypot(9.0, 3.0), 1e-12);
}

TEST(ThetaStarTest, BendsAroundAWall) {
  const OccupancyGrid grid = AsciiGrid({
      "..........",
      "....#.....",
      "....#.....",
      "....#.....",
      "..........",
  });
  const GridCollisionChecker checker(grid);
  const GridSearchResult theta = ThetaStar(grid, checker, {0, 2}, {9, 2});
  const GridSearchResult astar = SearchGrid(grid, {0, 2}, {9, 2});
  ASSERT_TRUE(theta.found);
  ASSERT_TRUE(astar.found);
  EXPECT_LT(theta.length, astar.length);
  EXPECT_GT(theta.length, StraightLine(grid, {0, 2}, {9, 2}));
  EXPECT_GE(theta.cells.size(), 3u);
  EXPECT_TRUE(checker.PathFree(CellPathToWorld(grid, theta.cells), 0.0));
}

TEST(ThetaStarTest, UnreachableAndTrivial) {
  const OccupancyGrid grid = AsciiGrid({".....", ".###.", ".#.#.", ".###.", "....."});
  const GridCollisionChecker checker(grid);
  EXPECT_FALSE(ThetaStar(grid, checker, {0, 0}, {2, 2}).found);
  const GridSearchResult same = ThetaStar(grid, checker, {4, 4}, {4, 4});
  ASSERT_TRUE(same.found);
  EXPECT_EQ(same.cells.size(), 1u);
  EXPECT_EQ(same.length, 0.0);
}

// On random grids: found exactly when A* finds a path, never longer than A*'s path, never
// shorter than the straight line, and collision-free by the grid's CollisionChecker.
TEST(ThetaStarTest, NoLongerThanAStarAndCollisionFreeOnRandomGrids) {
  GridSearchContext context;
  int found = 0;
  for (uint64_t seed = 1; seed <= 120; ++seed) {
    const OccupancyGrid grid = RandomGrid(36, 28, 0.22, seed);
    const GridCollisionChecker checker(grid);
    Rng rng(seed * 31);
    const Cell from = RandomFreeCell(grid, rng);
    const Cell to = RandomFreeCell(grid, rng);
    const GridSearchResult astar = SearchGrid(grid, from, to, {}, &context);
    const GridSearchResult theta = ThetaStar(grid, checker, from, to, {}, &context);
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    ASSERT_EQ(theta.found, astar.found);
    if (!theta.found) continue;
    ++found;
    EXPECT_EQ(theta.cells.front(), from);
    EXPECT_EQ(theta.cells.back(), to);
    EXPECT_LE(theta.length, astar.length + 1e-9);
    EXPECT_GE(theta.length, StraightLine(grid, from, to) - 1e-9);
    const Path path = CellPathToWorld(grid, theta.cells);
    EXPECT_NEAR(theta.length, PathLength(path), 1e-9);
    EXPECT_TRUE(checker.PathFree(path, 0.0));
  }
  EXPECT_GT(found, 60);
}

TEST(ThetaStarTest, KeepsClearance) {
  int found = 0;
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    const OccupancyGrid grid = RandomGrid(40, 40, 0.04, seed);
    const GridCollisionChecker checker(grid);
    Rng rng(seed);
    for (double clearance : {0.5, 1.0}) {
      GridSearchOptions options;
      options.clearance = clearance;
      const Cell from = RandomFreeCell(grid, rng);
      const Cell to = RandomFreeCell(grid, rng);
      const GridSearchResult theta = ThetaStar(grid, checker, from, to, options);
      const GridSearchResult astar = SearchGrid(grid, from, to, options);
      SCOPED_TRACE(testing::Message() << "seed " << seed << " clearance " << clearance);
      ASSERT_EQ(theta.found, astar.found);
      if (!theta.found) continue;
      ++found;
      EXPECT_LE(theta.length, astar.length + 1e-9);
      // Grid moves keep the clearance exactly (see grid_search.h); the checker's segment
      // clearance is a lower bound up to resolution / 8 below the truth.
      EXPECT_GE(checker.PathClearance(CellPathToWorld(grid, theta.cells)),
                clearance - grid.resolution() / 8 - 1e-9);
    }
  }
  EXPECT_GT(found, 20);
}

}  // namespace
}  // namespace swarmplan
