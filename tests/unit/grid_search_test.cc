#include "core/graph/grid_search.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "absl/strings/str_join.h"
#include "core/map/io/map_io.h"
#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

constexpr double kSqrt2 = 1.41421356237309504880;

// Rows of ASCII art, first row y = 0: '.' free, '#' blocked.
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

GridSearchOptions Options(GridConnectivity connectivity, bool corner_cutting, bool heuristic = true,
                          double clearance = 0.0) {
  GridSearchOptions o;
  o.connectivity = connectivity;
  o.allow_corner_cutting = corner_cutting;
  o.use_heuristic = heuristic;
  o.clearance = clearance;
  return o;
}

// Checks a found path: ends, neighbouring steps, every step allowed, length consistent.
void ExpectValidPath(const OccupancyGrid& grid, const GridSearchResult& r, Cell from, Cell to,
                     const GridSearchOptions& options) {
  ASSERT_TRUE(r.found);
  ASSERT_FALSE(r.cells.empty());
  EXPECT_EQ(r.cells.front(), from);
  EXPECT_EQ(r.cells.back(), to);
  for (const Cell& c : r.cells) {
    EXPECT_TRUE(CellUsable(grid, c, options.clearance)) << c.x << "," << c.y;
  }
  for (size_t i = 1; i < r.cells.size(); ++i) {
    const Cell a = r.cells[i - 1], b = r.cells[i];
    EXPECT_EQ(std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)), 1);
    EXPECT_TRUE(GridMoveAllowed(grid, a, b, options))
        << a.x << "," << a.y << " -> " << b.x << "," << b.y;
  }
  EXPECT_NEAR(r.length, CellPathLength(grid, r.cells), 1e-9);
}

// Reference distances computed independently of the search code: Bellman-Ford style relaxation
// until nothing changes, with the move rules written out again here.
std::vector<double> ReferenceDistances(const OccupancyGrid& grid, Cell from, bool eight,
                                       bool cutting) {
  const int w = grid.width(), h = grid.height();
  std::vector<double> d(static_cast<size_t>(w) * h, std::numeric_limits<double>::infinity());
  d[from.y * w + from.x] = 0;
  bool changed = true;
  while (changed) {
    changed = false;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (grid.IsBlocked(x, y)) continue;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const int nx = x + dx, ny = y + dy;
            if (grid.IsBlocked(nx, ny)) continue;
            const bool diagonal = dx != 0 && dy != 0;
            if (diagonal && !eight) continue;
            if (diagonal && !cutting && (grid.IsBlocked(x + dx, y) || grid.IsBlocked(x, y + dy))) {
              continue;
            }
            const double via = d[y * w + x] + (diagonal ? kSqrt2 : 1.0);
            if (via < d[ny * w + nx] - 1e-12) {
              d[ny * w + nx] = via;
              changed = true;
            }
          }
        }
      }
    }
  }
  return d;
}

TEST(GridSearchTest, OpenGridOctileAndManhattan) {
  const OccupancyGrid grid = AsciiGrid({".....", ".....", ".....", ".....", "....."});
  const GridSearchResult eight = SearchGrid(grid, {0, 0}, {4, 4});
  ASSERT_TRUE(eight.found);
  EXPECT_NEAR(eight.length, 4 * kSqrt2, 1e-12);
  EXPECT_EQ(eight.cells.size(), 5u);
  const GridSearchResult four =
      SearchGrid(grid, {0, 0}, {4, 4}, Options(GridConnectivity::kFour, false));
  ASSERT_TRUE(four.found);
  EXPECT_NEAR(four.length, 8.0, 1e-12);
  EXPECT_EQ(four.cells.size(), 9u);
  const GridSearchResult knight = SearchGrid(grid, {0, 0}, {4, 1});
  EXPECT_NEAR(knight.length, 3 + kSqrt2, 1e-12);
}

TEST(GridSearchTest, NoCornerCuttingByDefault) {
  // A blocked corner: the diagonal (0,0)->(1,1) passes next to the blocked (0,1).
  const OccupancyGrid corner = AsciiGrid({"..", "#."});
  const GridSearchResult strict = SearchGrid(corner, {0, 0}, {1, 1});
  ASSERT_TRUE(strict.found);
  EXPECT_NEAR(strict.length, 2.0, 1e-12);
  const GridSearchResult cut =
      SearchGrid(corner, {0, 0}, {1, 1}, Options(GridConnectivity::kEight, true));
  ASSERT_TRUE(cut.found);
  EXPECT_NEAR(cut.length, kSqrt2, 1e-12);

  // Two diagonally touching obstacles: no squeezing between them unless cutting is allowed.
  const OccupancyGrid squeeze = AsciiGrid({".#", "#."});
  EXPECT_FALSE(SearchGrid(squeeze, {0, 0}, {1, 1}).found);
  EXPECT_TRUE(SearchGrid(squeeze, {0, 0}, {1, 1}, Options(GridConnectivity::kEight, true)).found);
  EXPECT_FALSE(GridMoveAllowed(squeeze, {0, 0}, {1, 1}));
}

TEST(GridSearchTest, AroundAWall) {
  const OccupancyGrid grid = AsciiGrid({
      ".......",
      "...#...",
      "...#...",
      "...#...",
      ".......",
  });
  const GridSearchResult r = SearchGrid(grid, {0, 2}, {6, 2});
  ExpectValidPath(grid, r, {0, 2}, {6, 2}, {});
  EXPECT_NEAR(r.length, 2 + 4 * kSqrt2, 1e-12);
  const GridSearchOptions four = Options(GridConnectivity::kFour, false);
  const GridSearchResult r4 = SearchGrid(grid, {0, 2}, {6, 2}, four);
  ExpectValidPath(grid, r4, {0, 2}, {6, 2}, four);
  EXPECT_NEAR(r4.length, 10.0, 1e-12);
}

TEST(GridSearchTest, UnreachableGoal) {
  const OccupancyGrid grid = AsciiGrid({
      ".....",
      ".###.",
      ".#.#.",
      ".###.",
      ".....",
  });
  for (bool cutting : {false, true}) {
    const GridSearchResult r =
        SearchGrid(grid, {0, 0}, {2, 2}, Options(GridConnectivity::kEight, cutting));
    EXPECT_FALSE(r.found);
    EXPECT_TRUE(r.cells.empty());
    EXPECT_FALSE(r.stopped);
    EXPECT_GT(r.expanded, 0);
  }
  EXPECT_FALSE(AStarCells(grid, {0, 0}, {2, 2}).has_value());
  // Blocked or outside ends: nothing to search.
  EXPECT_FALSE(SearchGrid(grid, {1, 1}, {0, 0}).found);
  EXPECT_FALSE(SearchGrid(grid, {0, 0}, {5, 0}).found);
  EXPECT_FALSE(SearchGrid(grid, {-1, 0}, {0, 0}).found);
}

TEST(GridSearchTest, StartEqualsGoal) {
  const OccupancyGrid grid = AsciiGrid({"...", ".#.", "..."});
  const GridSearchResult r = SearchGrid(grid, {2, 1}, {2, 1});
  ASSERT_TRUE(r.found);
  ASSERT_EQ(r.cells.size(), 1u);
  EXPECT_EQ(r.cells[0], (Cell{2, 1}));
  EXPECT_EQ(r.length, 0.0);
}

TEST(GridSearchTest, MatchesIndependentReferenceOnRandomGrids) {
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    const OccupancyGrid grid = RandomGrid(14, 11, 0.3, seed);
    Rng rng(seed * 7919);
    const Cell from = RandomFreeCell(grid, rng);
    const Cell to = RandomFreeCell(grid, rng);
    for (bool eight : {true, false}) {
      for (bool cutting : {false, true}) {
        const std::vector<double> ref = ReferenceDistances(grid, from, eight, cutting);
        const double expected = ref[to.y * grid.width() + to.x];
        const GridSearchOptions options =
            Options(eight ? GridConnectivity::kEight : GridConnectivity::kFour, cutting);
        const GridSearchResult r = SearchGrid(grid, from, to, options);
        SCOPED_TRACE(testing::Message()
                     << "seed " << seed << " eight " << eight << " cutting " << cutting);
        if (std::isinf(expected)) {
          EXPECT_FALSE(r.found);
          continue;
        }
        ExpectValidPath(grid, r, from, to, options);
        EXPECT_NEAR(r.length, expected, 1e-9);
      }
    }
  }
}

TEST(GridSearchTest, AStarEqualsDijkstraOnRandomGrids) {
  GridSearchContext context;  // one context reused by every search
  int found = 0;
  for (uint64_t seed = 1; seed <= 150; ++seed) {
    const OccupancyGrid grid = RandomGrid(40 + static_cast<int>(seed % 7), 30, 0.25, seed);
    Rng rng(seed);
    const Cell from = RandomFreeCell(grid, rng);
    const Cell to = RandomFreeCell(grid, rng);
    for (GridConnectivity connectivity : {GridConnectivity::kEight, GridConnectivity::kFour}) {
      const GridSearchOptions astar = Options(connectivity, false, true);
      const GridSearchOptions dijkstra = Options(connectivity, false, false);
      const GridSearchResult a = SearchGrid(grid, from, to, astar, &context);
      const GridSearchResult d = SearchGrid(grid, from, to, dijkstra, &context);
      SCOPED_TRACE(testing::Message() << "seed " << seed);
      ASSERT_EQ(a.found, d.found);
      if (!a.found) continue;
      ++found;
      ExpectValidPath(grid, a, from, to, astar);
      ExpectValidPath(grid, d, from, to, dijkstra);
      EXPECT_NEAR(a.length, d.length, 1e-9);
      EXPECT_LE(a.expanded, d.expanded);
    }
  }
  EXPECT_GT(found, 150);  // most random problems are solvable: the test is not vacuous
}

TEST(GridSearchTest, DeterministicAndContextIndependent) {
  const OccupancyGrid big = RandomGrid(64, 64, 0.2, 3);
  const OccupancyGrid small = RandomGrid(9, 7, 0.1, 4);
  GridSearchContext shared;
  const GridSearchResult first = SearchGrid(big, {0, 0}, {63, 63}, {}, &shared);
  SearchGrid(small, {0, 0}, {8, 6}, {}, &shared);
  const GridSearchResult again = SearchGrid(big, {0, 0}, {63, 63}, {}, &shared);
  const GridSearchResult fresh = SearchGrid(big, {0, 0}, {63, 63});
  ASSERT_EQ(first.found, fresh.found);
  ASSERT_EQ(again.cells.size(), fresh.cells.size());
  for (size_t i = 0; i < fresh.cells.size(); ++i) EXPECT_EQ(again.cells[i], fresh.cells[i]);
  EXPECT_EQ(again.expanded, fresh.expanded);
  EXPECT_EQ(first.expanded, fresh.expanded);
}

TEST(GridSearchTest, LengthScalesWithResolution) {
  std::vector<int8_t> cells(6 * 4, 0);
  const OccupancyGrid grid = *OccupancyGrid::Create(6, 4, cells, 0.25, Point2(10, -3));
  const GridSearchResult r = SearchGrid(grid, {0, 0}, {5, 2});
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.length, 0.25 * (3 + 2 * kSqrt2), 1e-12);
  const Path world = CellPathToWorld(grid, r.cells);
  ASSERT_EQ(world.size(), r.cells.size());
  EXPECT_NEAR(world.front().x(), 10.125, 1e-12);
  EXPECT_NEAR(world.front().y(), -2.875, 1e-12);
  EXPECT_EQ(world.front().z(), 0.0);
}

TEST(GridSearchTest, CellCenterClearanceIsExact) {
  const OccupancyGrid grid = RandomGrid(25, 20, 0.08, 11);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      double brute = grid.IsBlocked(x, y) ? 0.0 : std::numeric_limits<double>::infinity();
      for (int by = 0; by < grid.height() && !grid.IsBlocked(x, y); ++by) {
        for (int bx = 0; bx < grid.width(); ++bx) {
          if (!grid.IsBlocked(bx, by)) continue;
          const double gx = std::max(std::abs(bx - x) - 0.5, 0.0);
          const double gy = std::max(std::abs(by - y) - 0.5, 0.0);
          brute = std::min(brute, std::hypot(gx, gy));
        }
      }
      EXPECT_NEAR(CellCenterClearance(grid, {x, y}), brute, 1e-12) << x << "," << y;
      for (double c : {0.5, 0.7, 1.2, 1.5, 2.0}) {
        EXPECT_EQ(CellUsable(grid, {x, y}, c), brute >= c) << x << "," << y << " c " << c;
      }
    }
  }
}

TEST(GridSearchTest, CellUsableWithoutFieldAgreesWithCellUsable) {
  constexpr double kHalfDiagonal = kSqrt2 / 2;
  struct Case {
    int width, height;
    double blocked_ratio, resolution;
  };
  const Case cases[] = {{30, 25, 0.08, 1.0},
                        {40, 40, 0.005, 0.3},
                        {3, 200, 0.02, 2.5},
                        {200, 2, 0.01, 0.7},
                        {12, 12, 0.0, 1.0}};
  uint64_t seed = 21;
  for (const Case& k : cases) {
    std::vector<int8_t> cells(static_cast<size_t>(k.width) * k.height);
    Rng rng(seed++);
    for (int8_t& c : cells) c = rng.Bernoulli(k.blocked_ratio) ? OccupancyGrid::kOccupied : 0;
    const OccupancyGrid grid = *OccupancyGrid::Create(k.width, k.height, cells, k.resolution);
    for (int y = 0; y < grid.height(); ++y) {
      for (int x = 0; x < grid.width(); ++x) {
        const double r = k.resolution;
        std::vector<double> clearances = {0.0, 0.4 * r, r, 1.3 * r, 4.2 * r, 1e3 * r};
        // The thresholds CellUsable compares against, where rounding would show.
        for (int n = 1; n < 40; ++n) {
          const double d = std::sqrt(static_cast<double>(n)) * r;
          clearances.push_back(d - r / 2);
          clearances.push_back(d - r * kHalfDiagonal);
        }
        for (double c : clearances) {
          ASSERT_EQ(CellUsableWithoutField(grid, {x, y}, c), CellUsable(grid, {x, y}, c))
              << k.width << "x" << k.height << " cell " << x << "," << y << " clearance " << c;
        }
      }
    }
  }
}

TEST(GridSearchTest, CellUsableWithoutFieldLeavesTheFieldUncomputed) {
  const OccupancyGrid grid = RandomGrid(50, 50, 0.05, 3);
  for (int x = 0; x < 50; ++x) CellUsableWithoutField(grid, {x, 7}, 2.5);
  EXPECT_FALSE(grid.distance_field_computed());
  CellUsable(grid, {3, 7}, 2.5);
  EXPECT_TRUE(grid.distance_field_computed());
}

TEST(GridSearchTest, ClearanceKeepsAwayFromObstacles) {
  const OccupancyGrid grid = AsciiGrid({
      "..........",
      "..........",
      "..........",
      "....##....",
      "....##....",
      "..........",
      "..........",
      "..........",
  });
  const GridSearchResult plain = SearchGrid(grid, {0, 4}, {9, 3});
  ASSERT_TRUE(plain.found);
  for (double clearance : {0.5, 1.0, 1.5}) {
    const GridSearchOptions options = Options(GridConnectivity::kEight, false, true, clearance);
    const GridSearchResult r = SearchGrid(grid, {0, 4}, {9, 3}, options);
    SCOPED_TRACE(testing::Message() << "clearance " << clearance);
    ExpectValidPath(grid, r, {0, 4}, {9, 3}, options);
    for (const Cell& c : r.cells) EXPECT_GE(CellCenterClearance(grid, c), clearance);
    EXPECT_GE(r.length, plain.length - 1e-12);
    const GridSearchResult d = SearchGrid(
        grid, {0, 4}, {9, 3}, Options(GridConnectivity::kEight, false, false, clearance));
    EXPECT_NEAR(d.length, r.length, 1e-9);
  }
  // Too much clearance: the obstacle leaves no room (rows 0..7, the block at rows 3-4).
  EXPECT_FALSE(
      SearchGrid(grid, {0, 0}, {9, 7}, Options(GridConnectivity::kEight, false, true, 3.0)).found);
}

TEST(GridSearchTest, StopsAtExpansionCapAndOnCancel) {
  const OccupancyGrid grid = RandomGrid(200, 200, 0.1, 5);
  GridSearchOptions capped;
  capped.max_expansions = 10;
  const GridSearchResult r = SearchGrid(grid, {0, 0}, {199, 199}, capped);
  EXPECT_FALSE(r.found);
  EXPECT_TRUE(r.stopped);
  EXPECT_EQ(r.expanded, 10);

  StopToken stop;
  stop.Cancel();
  GridSearchOptions cancelled;
  cancelled.stop = &stop;
  cancelled.use_heuristic = false;  // explores the whole grid unless stopped
  const GridSearchResult c = SearchGrid(grid, {0, 0}, {199, 199}, cancelled);
  EXPECT_TRUE(c.stopped);
  EXPECT_FALSE(c.found);
  EXPECT_LT(c.expanded, 10000);
}

}  // namespace
}  // namespace swarmplan
