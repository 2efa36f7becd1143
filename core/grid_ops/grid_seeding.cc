#include "core/grid_ops/grid_seeding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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
    const GridPathCost::Judged judged = out.cost_.Smoothed(seed.path);
    if (out.best_path_.empty() || judged < out.best_judged_) {
      out.best_path_ = seed.path;
      out.best_judged_ = judged;
    }
  }
  if (out.cell_paths_.empty()) {
    return absl::NotFoundError("init=seeded: no seed path from start to goal on the planning grid");
  }
  out.best_cost_ = out.cost_.Cost(out.best_path_);
  return out;
}

double GridSeeds::Cost(const std::vector<Cell>& cells) {
  if (!cost_.judges_after_smoothing()) return cost_(cells);
  std::optional<Path> path = cost_.PathOf(cells);
  if (!path) return std::numeric_limits<double>::infinity();
  const double cost = cost_.Cost(*path);
  Remember(*std::move(path), cost);
  return cost;
}

void GridSeeds::Remember(Path path, double cost) {
  if (shortlist_.size() == kShortlist && cost >= shortlist_.back().first) return;
  for (const auto& [kept_cost, kept] : shortlist_) {
    if (kept_cost == cost && kept == path) return;
  }
  const auto at = std::upper_bound(shortlist_.begin(), shortlist_.end(), cost,
                                   [](double c, const auto& entry) { return c < entry.first; });
  shortlist_.insert(at, {cost, std::move(path)});
  if (shortlist_.size() > kShortlist) shortlist_.pop_back();
}

bool GridSeeds::SetResult(const std::vector<Cell>& best_cells, const StopToken& stop,
                          SearchResult& result) {
  std::vector<Path> candidates;
  if (std::optional<Path> path = cost_.PathOf(best_cells)) candidates.push_back(*std::move(path));
  for (auto& [cost, path] : shortlist_) {
    if (std::find(candidates.begin(), candidates.end(), path) == candidates.end()) {
      candidates.push_back(std::move(path));
    }
  }
  shortlist_.clear();
  const Path* best = nullptr;
  GridPathCost::Judged best_judged = best_judged_;
  for (const Path& candidate : candidates) {
    if (&candidate != &candidates.front() && stop.Check(0) != StopReason::kNone) break;
    const GridPathCost::Judged judged = cost_.Smoothed(candidate);
    if (judged < best_judged) {
      best = &candidate;
      best_judged = judged;
    }
  }
  const bool keep_seed = best == nullptr;
  result.fitness = keep_seed ? best_cost_ : cost_.Cost(*best);
  result.path = keep_seed ? best_path_ : *best;
  result.found = cost_.space().PathFree(result.path);
  result.seed_path = best_path_;
  return keep_seed;
}

}  // namespace swarmplan
