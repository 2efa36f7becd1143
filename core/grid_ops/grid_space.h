#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/clock.h"
#include "core/geometry/collision.h"
#include "core/map/occupancy_grid.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/problem.h"

namespace swarmplan {

// The grid a grid planner searches: the problem's own occupancy grid, or its ShapeWorld
// rasterised (a cell is blocked when any part of it is inside an obstacle), with start and goal
// as cells. The world path of a cell path runs from the exact start to the exact goal: at each
// end the end cell's centre is replaced by the point when the segment from the point to the
// next centre is collision-free on the problem's own map, and joined to the point otherwise
// (see WorldPath). Its length (PathLength) is the fitness every grid planner minimises.
class GridSpace {
 public:
  std::shared_ptr<const OccupancyGrid> grid;
  Cell start;
  Cell goal;

  // The path through the cells' centres with the ends attached as described above; empty when
  // `cells` is. `cells` runs from `start` to `goal`.
  Path WorldPath(const std::vector<Cell>& cells) const;
  // Length of WorldPath(cells) in world units, without building it: CellPathLength (octile
  // step counts) corrected at the ends.
  double PathLength(const std::vector<Cell>& cells) const;
  // Whether WorldPath(cells) keeps the clearance on the problem's own map (exact checker).
  bool PathFree(const Path& world_path) const;
  // Whether the straight segment between two world points keeps the clearance (exact checker).
  bool SegmentFree(const Point3& a, const Point3& b) const;
  // The centre of a cell in world coordinates, z = 0.
  Point3 Centre(Cell c) const;

 private:
  friend absl::StatusOr<GridSpace> MakeGridSpace(const Problem& problem, double resolution);
  // How the ends of a cell path are attached: an end cell's centre replaced by the point, or
  // the point joined to it.
  struct Ends {
    bool replace_start = false;
    bool replace_goal = false;
  };
  Ends EndsOf(const std::vector<Cell>& cells) const;
  // Whether the segment from the start point to the centre of `next` (from the centre of
  // `previous` to the goal point) is collision-free.
  bool StartSegmentFree(Cell next) const;
  bool GoalSegmentFree(Cell previous) const;

  MapPtr map_;  // keeps the checker's map alive
  std::shared_ptr<const CollisionChecker> checker_;
  double clearance_ = 0.0;
  Point3 start_point_ = Point3::Zero();  // z = 0
  Point3 goal_point_ = Point3::Zero();
  // StartSegmentFree / GoalSegmentFree for the eight neighbours (and the cell itself), indexed
  // by (dy + 1) * 3 + (dx + 1); and whether the segment from start to goal is free.
  std::array<bool, 9> start_free_{};
  std::array<bool, 9> goal_free_{};
  bool direct_free_ = false;
};

// The resolution a shape world is rasterised at when the `resolution` parameter is 0 ("auto"):
// the world's longer side / 64 (grids of the size the grid-node papers plan on), made finer
// where needed so that the start and goal cells are usable: at most (d - clearance) / (1.5 sqrt 2)
// for an endpoint d from the nearest obstacle (then its cell is free and the cell's centre keeps
// the clearance from every blocked cell), halved further while an end cell is still unusable (a
// point near the raster's edge); never finer than a raster of kMaxAutoRasterCells cells.
inline constexpr double kAutoRasterCellsPerSide = 64.0;
inline constexpr int64_t kMaxAutoRasterCells = 1 << 20;

// `resolution` is used for shape worlds only; 0 chooses it automatically (above). Errors:
// FAILED_PRECONDITION when start or goal lies outside the grid or in a cell that is not usable
// for the clearance (the message names the cell and the resolution); INVALID_ARGUMENT for a map
// kind without a grid (terrain).
absl::StatusOr<GridSpace> MakeGridSpace(const Problem& problem, double resolution);

// The parameters every grid-node planner declares: `allow_corner_cutting` (diagonal steps may
// pass a blocked corner; default false) and `resolution` (cell size when a shape world is
// rasterised; default 0, automatic; ours). Fish swarms have no corner rule: they take only the
// resolution.
std::vector<ParamSpec> GridSpaceParamSpecs(bool with_corner_cutting = true);

// Fills path (space.WorldPath(cells)), fitness and found (the path is collision-free on the
// problem's own map, checked exactly) from a cell path; leaves the path empty and found false
// when `cells` is empty. `fitness` should be space.PathLength(cells) for a path.
void SetGridPath(const GridSpace& space, const std::vector<Cell>& cells, double fitness,
                 SearchResult& result);

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
