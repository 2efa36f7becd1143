#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "absl/status/statusor.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/grid_moves.h"
#include "core/grid_ops/grid_path_cost.h"
#include "core/grid_ops/grid_space.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/problem.h"
#include "core/stop_token.h"

namespace swarmplan {

// How a grid-node planner initialises (parameters `init` and `seeds`, named as for the waypoint
// planners). init=seeded, the parameters' default: the population starts from the seed paths,
// the fitness is the request's objective of the any-angle path (GridPathCost: the length, or the
// fleet objective when the request states preferences) and the result is never worse than the
// best seed. init=paper: the paper's initialisation and cell-path fitness. A directly
// constructed planner runs the paper's.
struct GridSeeding {
  bool seeded = false;
  int seeds = 3;
};
std::vector<ParamSpec> GridSeedingParams();
GridSeeding GridSeedingFrom(const ParamSet& params);

// The seed polyline as a cell path of the grid space valid under `moves`, from space.start to
// space.goal: the usable cells the polyline passes through (sampled a quarter cell apart), in
// order, joined by A* where two are not a valid move, loops removed. nullopt when a gap cannot
// be joined.
std::optional<std::vector<Cell>> SeedCellPath(const GridSpace& space, GridMoves& moves,
                                              const Path& seed, GridSearchContext* context);

// The seeded initialisation of a grid-node planner (init=seeded): the problem's seed paths
// (FindSeedPaths, exact optimum first), each as a cell path of the planner's grid space and
// moves, the fitness every seeded grid planner ranks its cell paths by (GridPathCost), and the
// best seed as the plan judges it (GridPathCost::Smoothed: with a turning radius, after the
// smoothing) as the incumbent from iteration 0: the result is never worse than the best seed.
class GridSeeds {
 public:
  // Up to `count` seeds. Errors: FindSeedPaths' and GridPathCost's; NOT_FOUND when no path
  // exists or no seed can be turned into a cell path. `space` must outlive the seeds.
  static absl::StatusOr<GridSeeds> Find(const Problem& problem, const GridSpace& space,
                                        GridMoves& moves, int count, const StopToken& stop,
                                        GridSearchContext* context);

  // At least one, in the order of the seeds.
  const std::vector<std::vector<Cell>>& cell_paths() const { return cell_paths_; }
  // The cell path population member `i` starts from: the seeds in turn.
  const std::vector<Cell>& ForMember(size_t i) const { return cell_paths_[i % cell_paths_.size()]; }
  // The fitness of a cell path: the objective of its any-angle path. Where the plan judges
  // paths after a smoothing, the few best paths ranked here are kept for SetResult.
  double Cost(const std::vector<Cell>& cells);
  double best_cost() const { return best_cost_; }
  // The best fitness so far once the best seed counts: min(fitness, best_cost()).
  double Incumbent(double fitness) const { return fitness < best_cost_ ? fitness : best_cost_; }

  // The result's path is the best of best_cells' any-angle path, the few best paths Cost ranked
  // (while `stop` lets the plan run on) and the best seed as the plan judges them, its fitness
  // that path's Cost, found when it is collision-free; its seed_path the best seed.
  // True when the seed is kept.
  bool SetResult(const std::vector<Cell>& best_cells, const StopToken& stop, SearchResult& result);

 private:
  explicit GridSeeds(GridPathCost cost) : cost_(std::move(cost)) {}

  // Keeps `path` among the kShortlist lowest costs seen.
  void Remember(Path path, double cost);

  static constexpr size_t kShortlist = 4;

  GridPathCost cost_;
  std::vector<std::pair<double, Path>> shortlist_;  // by cost, distinct paths
  std::vector<std::vector<Cell>> cell_paths_;
  Path best_path_;
  GridPathCost::Judged best_judged_;  // the best seed as the plan judges it
  double best_cost_ = 0.0;            // its Cost
};

}  // namespace swarmplan
