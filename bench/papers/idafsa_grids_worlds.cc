#include "bench/papers/idafsa_grids_worlds.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "core/grid_ops/cell_path.h"
#include "core/map/generate.h"

namespace swarmplan::bench {

const std::vector<IdafsaGridWorld>& IdafsaGridWorlds() {
  static const std::vector<IdafsaGridWorld>* const worlds = new std::vector<IdafsaGridWorld>{
      {"grid-10x10.txt", 10, 0.20, 2, 3001},
      {"grid-20x20.txt", 20, 0.25, 2, 3002},
  };
  return *worlds;
}

Cell IdafsaStart(const IdafsaGridWorld&) { return Cell{0, 0}; }

Cell IdafsaGoal(const IdafsaGridWorld& world) { return Cell{world.size - 1, world.size - 1}; }

absl::StatusOr<OccupancyGrid> GenerateIdafsaGrid(const IdafsaGridWorld& world) {
  absl::StatusOr<DrawnIdafsaGrid> drawn = DrawIdafsaGrid(world);
  if (!drawn.ok()) return drawn.status();
  return std::move(drawn->grid);
}

absl::StatusOr<DrawnIdafsaGrid> DrawIdafsaGrid(const IdafsaGridWorld& world) {
  RandomGridOptions options;
  options.width = world.size;
  options.height = world.size;
  options.obstacle_ratio = world.obstacle_ratio;
  options.block_size = world.block_size;
  const Cell start = IdafsaStart(world);
  const Cell goal = IdafsaGoal(world);
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      options.keep_free.push_back(Cell{start.x + dx, start.y + dy});
      options.keep_free.push_back(Cell{goal.x - dx, goal.y - dy});
    }
  }
  constexpr int kMaxTries = 1000;
  for (int i = 0; i < kMaxTries; ++i) {
    const uint64_t seed = world.seed + i;
    absl::StatusOr<OccupancyGrid> grid = RandomGrid(options, seed);
    if (!grid.ok()) return grid.status();
    if (FourConnected(*grid, start, goal)) return DrawnIdafsaGrid{*std::move(grid), seed};
  }
  return absl::InternalError(absl::StrCat(world.file, ": no seed from ", world.seed, " in ",
                                          kMaxTries, " joins start and goal"));
}

bool FourConnected(const OccupancyGrid& grid, Cell a, Cell b) {
  GridMoves moves(grid, MoveRules{Neighbourhood::k4, /*segment_check=*/true, 0.0});
  if (!moves.Usable(a) || !moves.Usable(b)) return false;
  const std::vector<Cell> reachable = ReachableCells(moves, a);
  return std::find(reachable.begin(), reachable.end(), b) != reachable.end();
}

std::optional<double> MoveSetOptimum(const OccupancyGrid& grid, Neighbourhood neighbourhood,
                                     Cell start, Cell goal) {
  GridMoves moves(grid, MoveRules{neighbourhood, /*segment_check=*/true, 0.0});
  if (!moves.Usable(start) || !moves.Usable(goal)) return std::nullopt;
  const auto index = [&](Cell c) { return static_cast<size_t>(c.y) * grid.width() + c.x; };
  std::vector<double> dist(static_cast<size_t>(grid.width()) * grid.height(),
                           std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  dist[index(start)] = 0.0;
  open.push({0.0, index(start)});
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[i]) continue;
    const Cell c{static_cast<int>(i % grid.width()), static_cast<int>(i / grid.width())};
    if (c == goal) return d * grid.resolution();
    for (const Cell& n : moves.ValidMoves(c)) {
      const double nd = d + std::hypot(n.x - c.x, n.y - c.y);
      if (nd < dist[index(n)]) {
        dist[index(n)] = nd;
        open.push({nd, index(n)});
      }
    }
  }
  return std::nullopt;
}

bool PassesThroughBlockedCell(const OccupancyGrid& grid, const Path& path) {
  constexpr double kInset = 1e-6;
  const double r = grid.resolution();
  for (size_t i = 1; i < path.size(); ++i) {
    const Point2 a = path[i - 1].head<2>();
    const Point2 b = path[i].head<2>();
    for (const Cell& c : CellsTouchedBySegment(grid.CellAt(a), grid.CellAt(b))) {
      if (!grid.IsBlocked(c) || !grid.InBounds(c)) continue;
      const Point2 lo = grid.origin() + Point2(c.x, c.y) * r + Point2(kInset, kInset);
      const Point2 hi = grid.origin() + Point2(c.x + 1, c.y + 1) * r - Point2(kInset, kInset);
      if (SegmentBoxDistance(a, b, lo, hi) == 0.0) return true;
    }
  }
  return false;
}

}  // namespace swarmplan::bench
