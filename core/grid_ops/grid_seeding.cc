#include "core/grid_ops/grid_seeding.h"

#include <algorithm>
#include <cmath>

#include "absl/status/status.h"
#include "core/grid_ops/cell_path.h"
#include "core/grid_ops/shortcut.h"
#include "core/operators/waypoint_params.h"
#include "core/path_metrics.h"
#include "core/seeds/seed_paths.h"

namespace swarmplan {

std::vector<ParamSpec> GridSeedingParams() {
  return SeedingParams(
      "the population starts from exact seed paths in distinct corridors turned into cell paths, "
      "the paper's operators search from there, moves may take line-of-sight steps, and paths "
      "are ranked by the request's objective (the length, or the fleet objective when it states "
      "preferences) of their any-angle path after line-of-sight shortcutting; the result is "
      "never worse than the best seed",
      "the paper's initialisation and fitness (cell-path length)");
}

GridSeeding GridSeedingFrom(const ParamSet& params) {
  GridSeeding seeding;
  seeding.seeded = params.Enum("init") == "seeded";
  seeding.seeds = static_cast<int>(params.Int("seeds"));
  return seeding;
}

std::optional<std::vector<Cell>> SeedCellPath(const GridSpace& space, GridMoves& moves,
                                              const Path& seed, GridSearchContext* context) {
  const OccupancyGrid& grid = *space.grid;
  const double spacing = grid.resolution() / 4.0;
  std::vector<Cell> cells{space.start};
  auto visit = [&](const Point3& p) {
    const Cell c = grid.CellAt(Point2(p.x(), p.y()));
    if (moves.Usable(c) && !(c == cells.back())) cells.push_back(c);
  };
  for (size_t i = 0; i + 1 < seed.size(); ++i) {
    const Point3 a = seed[i], b = seed[i + 1];
    const int samples = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int k = 0; k < samples; ++k) visit(a + (b - a) * (static_cast<double>(k) / samples));
  }
  if (!(cells.back() == space.goal)) cells.push_back(space.goal);
  RemoveLoops(cells);
  if (!RepairGaps(moves, cells, context)) return std::nullopt;
  RemoveLoops(cells);
  return cells;
}

absl::StatusOr<GridSeeds> GridSeeds::Find(const Problem& problem, const GridSpace& space,
                                          GridMoves& moves, int count, const StopToken& stop,
                                          GridSearchContext* context) {
  absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, count, stop);
  if (!seeds.ok()) return seeds.status();
  absl::StatusOr<GridPathCost> cost = GridPathCost::Create(problem, space);
  if (!cost.ok()) return cost.status();
  GridSeeds out(*std::move(cost));
  for (const SeedPath& seed : *seeds) {
    std::optional<std::vector<Cell>> cells = SeedCellPath(space, moves, seed.path, context);
    if (!cells) continue;
    out.cell_paths_.push_back(*std::move(cells));
    const double cost_of_seed = out.cost_.Cost(seed.path);
    if (out.best_path_.empty() || cost_of_seed < out.best_cost_) {
      out.best_path_ = seed.path;
      out.best_cost_ = cost_of_seed;
    }
  }
  if (out.cell_paths_.empty()) {
    return absl::NotFoundError("init=seeded: no seed path from start to goal on the planning grid");
  }
  return out;
}

bool GridSeeds::SetResult(const std::vector<Cell>& best_cells, SearchResult& result) {
  std::optional<Path> path = cost_.PathOf(best_cells);
  const double path_cost = path ? cost_.Cost(*path) : best_cost_;
  const bool keep_seed = !path || path_cost >= best_cost_;
  result.path = keep_seed ? best_path_ : *std::move(path);
  result.fitness = keep_seed ? best_cost_ : path_cost;
  result.found = cost_.space().PathFree(result.path);
  result.seed_path = best_path_;
  return keep_seed;
}

}  // namespace swarmplan
