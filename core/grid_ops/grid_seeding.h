#pragma once

#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/grid_moves.h"
#include "core/grid_ops/grid_space.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/problem.h"
#include "core/stop_token.h"

namespace swarmplan {

// How a grid-node planner initialises (parameters `init` and `seeds`, named as for the waypoint
// planners). init=seeded, the parameters' default: the population starts from the seed paths,
// the fitness is the any-angle length (AnyAngleLength) and the result is never longer than the
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
// moves, and the best seed as the incumbent from iteration 0: the result is never longer than
// the best seed.
class GridSeeds {
 public:
  // Up to `count` seeds. Errors: FindSeedPaths'; NOT_FOUND when no path exists or no seed can be
  // turned into a cell path.
  static absl::StatusOr<GridSeeds> Find(const Problem& problem, const GridSpace& space,
                                        GridMoves& moves, int count, const StopToken& stop,
                                        GridSearchContext* context);

  // At least one, in the order of the seeds.
  const std::vector<std::vector<Cell>>& cell_paths() const { return cell_paths_; }
  // The cell path population member `i` starts from: the seeds in turn.
  const std::vector<Cell>& ForMember(size_t i) const { return cell_paths_[i % cell_paths_.size()]; }
  double best_length() const { return best_length_; }
  // The best fitness so far once the best seed counts: min(fitness, best_length()).
  double Incumbent(double fitness) const { return fitness < best_length_ ? fitness : best_length_; }

  // The result's path is the shorter of AnyAnglePath(best_cells) and the best seed, its
  // fitness that path's length, found when it is collision-free; its seed_path the best seed.
  // True when the seed is kept.
  bool SetResult(const GridSpace& space, const std::vector<Cell>& best_cells,
                 SearchResult& result) const;

 private:
  std::vector<std::vector<Cell>> cell_paths_;
  Path best_path_;
  double best_length_ = 0.0;
};

}  // namespace swarmplan
