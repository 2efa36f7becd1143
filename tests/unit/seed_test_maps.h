#pragma once

// Small maps with known corridors for the seed and seeded-planner tests, and the contract
// test's independent clearance of a 2D path.

#include <memory>
#include <utility>
#include <vector>

#include "core/map/map.h"
#include "core/problem.h"
#include "tests/unit/contract_checks.h"

namespace swarmplan::seed_testing {

// 40 x 30 cells, a wall along row 15 with doors at x in [4, 8) and [30, 34).
inline MapPtr TwoDoorGrid() {
  std::vector<int8_t> cells(40 * 30, OccupancyGrid::kFree);
  for (int x = 0; x < 40; ++x) {
    if ((x >= 4 && x < 8) || (x >= 30 && x < 34)) continue;
    cells[15 * 40 + x] = OccupancyGrid::kOccupied;
  }
  return std::make_shared<const Map>(Map::Data(*OccupancyGrid::Create(40, 30, std::move(cells))));
}

// 40 x 30 with a block [10, 30] x [12, 18] between start and goal.
inline MapPtr BlockWorld() {
  Polygon block{{{10, 12}, {30, 12}, {30, 18}, {10, 18}}};
  return std::make_shared<const Map>(
      Map::Data(*ShapeWorld::Create({{0, 0}, {40, 30}}, {}, {block})));
}

// A problem on `map` from start to goal with the clearance, seed 11.
inline Problem MakeProblem(const MapPtr& map, const Point2& start, const Point2& goal,
                           double clearance = 0.0) {
  Problem problem;
  problem.map = map;
  problem.start = Point3(start.x(), start.y(), 0);
  problem.goal = Point3(goal.x(), goal.y(), 0);
  problem.clearance = clearance;
  problem.seed = 11;
  return problem;
}

inline double Clearance(const Map& map, const Path& path) {
  if (const OccupancyGrid* grid = map.grid()) return contract::GridPathClearance(*grid, path);
  return contract::WorldPathClearance(*map.world(), path);
}

// Where the path first crosses the horizontal line y = row, or -1.
inline double CrossingX(const Path& path, double row) {
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const double y0 = path[i].y(), y1 = path[i + 1].y();
    if ((y0 - row) * (y1 - row) <= 0 && y0 != y1) {
      return path[i].x() + (row - y0) / (y1 - y0) * (path[i + 1].x() - path[i].x());
    }
  }
  return -1;
}

}  // namespace swarmplan::seed_testing
