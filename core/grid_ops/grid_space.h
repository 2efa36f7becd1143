#pragma once

#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/clock.h"
#include "core/map/occupancy_grid.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/problem.h"

namespace swarmplan {

// The grid a grid planner searches: the problem's own occupancy grid, or its ShapeWorld
// rasterised at `resolution` world units per cell (a cell is blocked when any part of it is
// inside an obstacle), with start and goal as cells.
struct GridSpace {
  std::shared_ptr<const OccupancyGrid> grid;
  Cell start;
  Cell goal;
};

// FAILED_PRECONDITION when start or goal lies outside the grid or in a cell that is not usable
// for the clearance; INVALID_ARGUMENT for a map kind without a grid (terrain).
absl::StatusOr<GridSpace> MakeGridSpace(const Problem& problem, double resolution);

// The parameters every grid-node planner declares: `allow_corner_cutting` (diagonal steps may
// pass a blocked corner; default false) and `resolution` (cell size when a shape world is
// rasterised; default 1 world unit, ours). Fish swarms have no corner rule: they take only the
// resolution.
std::vector<ParamSpec> GridSpaceParamSpecs(bool with_corner_cutting = true);

// Fills path (cell centres, z = 0), fitness and found (the path is collision-free on the
// problem's own map, checked exactly) from a cell path; leaves them empty when `cells` is.
void SetGridPath(const Problem& problem, const OccupancyGrid& grid, const std::vector<Cell>& cells,
                 double fitness, SearchResult& result);

// The per-iteration log every planner keeps: records IterationStats, streams them to the
// observer and keeps them for the result.
class ConvergenceLog {
 public:
  explicit ConvergenceLog(Observer& observer) : observer_(observer), start_(absl::Now()) {}

  void Record(int iteration, double best_fitness, double mean_fitness, int64_t evaluations,
              bool feasible) {
    IterationStats s;
    s.iteration = iteration;
    s.best_fitness = best_fitness;
    s.mean_fitness = mean_fitness;
    s.evaluations = evaluations;
    s.elapsed = absl::Now() - start_;
    s.feasible = feasible;
    stats_.push_back(s);
    observer_.OnIteration(s);
  }
  std::vector<IterationStats> Take() { return std::move(stats_); }

 private:
  Observer& observer_;
  absl::Time start_;
  std::vector<IterationStats> stats_;
};

}  // namespace swarmplan
