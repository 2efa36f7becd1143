#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/graph/grid_search.h"
#include "core/grid_ops/grid_moves.h"
#include "core/map/map.h"
#include "core/planner.h"
#include "core/problem.h"
#include "gtest/gtest.h"

namespace swarmplan::testing {

// A grid from rows of text ('#' blocked, anything else free); row i of the text is y = i.
inline OccupancyGrid GridFromRows(const std::vector<std::string>& rows, double resolution = 1.0) {
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows.front().size());
  std::vector<int8_t> cells(static_cast<size_t>(w) * h, OccupancyGrid::kFree);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (rows[y][x] == '#') cells[static_cast<size_t>(y) * w + x] = OccupancyGrid::kOccupied;
    }
  }
  return *OccupancyGrid::Create(w, h, std::move(cells), resolution);
}

inline MapPtr GridMap(const std::vector<std::string>& rows, double resolution = 1.0) {
  return std::make_shared<const Map>(GridFromRows(rows, resolution));
}

inline Problem GridProblemFor(const MapPtr& map, Cell start, Cell goal, uint64_t seed = 7) {
  Problem p;
  p.map = map;
  const OccupancyGrid& g = *map->grid();
  const Point2 s = g.CellCenter(start), t = g.CellCenter(goal);
  p.start = Point3(s.x(), s.y(), 0.0);
  p.goal = Point3(t.x(), t.y(), 0.0);
  p.seed = seed;
  return p;
}

// 10 x 10 with a few blocks between the corners, like the fish swarm paper's small map.
inline std::vector<std::string> FishSmallRows() {
  return {
      "..........",  //
      "..........",  //
      "..##......",  //
      "..##...#..",  //
      ".......#..",  //
      "....#..#..",  //
      "....#.....",  //
      "....#..##.",  //
      ".......##.",  //
      "..........",  //
  };
}

// 12 x 12 with two walls: the shortest path must bend twice.
inline std::vector<std::string> TwoWallsRows() {
  return {
      "............",  //
      "............",  //
      "...#........",  //
      "...#........",  //
      "...#....#...",  //
      "...#....#...",  //
      "...#....#...",  //
      "...#....#...",  //
      "........#...",  //
      "........#...",  //
      "............",  //
      "............",  //
  };
}

// The cells of a world path of cell centres.
inline std::vector<Cell> CellsOf(const OccupancyGrid& grid, const Path& path) {
  std::vector<Cell> cells;
  for (const Point3& p : path) cells.push_back(grid.CellAt(Point2(p.x(), p.y())));
  return cells;
}

inline double AStarLength(const OccupancyGrid& grid, Cell a, Cell b) {
  return SearchGrid(grid, a, b).length;
}

// Cancels on the first OnIteration it sees, and counts iterations.
class CancellingObserver final : public Observer {
 public:
  explicit CancellingObserver(const StopToken& stop, int cancel_at = 0)
      : stop_(stop), cancel_at_(cancel_at) {}
  void OnIteration(const IterationStats& s) override {
    ++count;
    last_best = s.best_fitness;
    if (s.iteration >= cancel_at_) stop_.Cancel();
  }
  int count = 0;
  double last_best = 0.0;

 private:
  StopToken stop_;
  int cancel_at_;
};

// The path starts and ends at the given cells' centres and every step is a valid move of the
// neighbourhood whose segment touches no blocked cell (corners included).
inline void ExpectValidGridPath(const OccupancyGrid& grid, const Path& path, Cell start, Cell goal,
                                Neighbourhood neighbourhood) {
  ASSERT_GE(path.size(), 2u);
  const std::vector<Cell> cells = CellsOf(grid, path);
  EXPECT_EQ(cells.front(), start);
  EXPECT_EQ(cells.back(), goal);
  GridMoves moves(grid, MoveRules{neighbourhood, true, 0.0});
  for (size_t i = 1; i < cells.size(); ++i) {
    EXPECT_TRUE(moves.IsMove(cells[i - 1], cells[i]))
        << "step " << i << ": (" << cells[i - 1].x << "," << cells[i - 1].y << ") -> ("
        << cells[i].x << "," << cells[i].y << ")";
  }
}

// Convergence log: one entry per iteration, numbered from 0, best fitness non-increasing.
template <typename Stats>
void ExpectMonotoneLog(const Stats& log, int iterations) {
  ASSERT_EQ(static_cast<int>(log.size()), iterations);
  for (size_t i = 0; i < log.size(); ++i) {
    EXPECT_EQ(log[i].iteration, static_cast<int>(i));
    if (i > 0) {
      EXPECT_LE(log[i].best_fitness, log[i - 1].best_fitness);
    }
  }
}

class RecordingObserver final : public Observer {
 public:
  void OnIteration(const IterationStats& s) override { stats.push_back(s); }
  std::vector<IterationStats> stats;
};

}  // namespace swarmplan::testing
