#pragma once

// The worlds of the IDAFSA reproduction (idafsa_grids.cc): seeded 10 x 10 and 20 x 20 grids with
// start and goal in opposite corners, and the references the report compares against.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/grid_ops/grid_moves.h"
#include "core/map/map.h"
#include "core/map/occupancy_grid.h"
#include "core/map/point.h"

namespace swarmplan::bench {

struct IdafsaGridWorld {
  std::string file;  // ASCII grid under bench/worlds/idafsa-grids/
  int size = 10;     // size x size cells
  double obstacle_ratio = 0.2;
  int block_size = 2;  // obstacles are squares of block_size cells
  uint64_t seed = 1;   // the first seed tried; the next ones until start and goal are connected
};

// The 10 x 10 and 20 x 20 worlds, in the order of the paper's Tables 2 and 3.
const std::vector<IdafsaGridWorld>& IdafsaGridWorlds();

// Start (0, 0) and goal (size - 1, size - 1): opposite corners, as in the paper's figures.
Cell IdafsaStart(const IdafsaGridWorld& world);
Cell IdafsaGoal(const IdafsaGridWorld& world);

// The world's grid: RandomGrid with the corners' 2 x 2 cells kept free, for the first seed from
// world.seed (at most 1000 tried) whose start and goal are joined by 4-connected free cells.
absl::StatusOr<OccupancyGrid> GenerateIdafsaGrid(const IdafsaGridWorld& world);

// The same grid with the seed it was drawn from.
struct DrawnIdafsaGrid {
  OccupancyGrid grid;
  uint64_t seed = 0;
};
absl::StatusOr<DrawnIdafsaGrid> DrawIdafsaGrid(const IdafsaGridWorld& world);

// Whether free cells joined by orthogonal steps lead from a to b.
bool FourConnected(const OccupancyGrid& grid, Cell a, Cell b);

// The length (cells) of the shortest path made of valid moves of the neighbourhood, every move's
// segment touching no blocked cell (Dijkstra over GridMoves); nullopt when there is none. With
// 24 this is the best a `dafsa` or `idafsa` path can be.
std::optional<double> MoveSetOptimum(const OccupancyGrid& grid, Neighbourhood neighbourhood,
                                     Cell start, Cell goal);

// Whether a polyline through cell centres enters the inside of a blocked cell (more than 1e-6 from
// its border), rather than only touching blocked corners or edges. Tells an `afsa` path that
// jumped an obstacle from one that cut a corner.
bool PassesThroughBlockedCell(const OccupancyGrid& grid, const Path& path);

}  // namespace swarmplan::bench
