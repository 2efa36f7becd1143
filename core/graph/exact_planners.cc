#include "core/graph/exact_planners.h"

#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "core/algorithms/exact/terrain_lattice_planner.h"
#include "core/algorithms/register.h"
#include "core/geometry/grid_collision.h"
#include "core/graph/grid_search.h"
#include "core/graph/theta_star.h"
#include "core/graph/visibility_graph.h"
#include "core/path_metrics.h"

namespace swarmplan {
namespace {

// An exact search is one iteration: the observer sees it once, with best = mean = length.
SearchResult FinishSearch(Path path, int64_t expanded, absl::Time started, Observer& observer) {
  SearchResult result;
  result.found = !path.empty();
  result.path = std::move(path);
  result.fitness = result.found ? PathLength(result.path) : 0.0;
  result.iterations = 1;
  result.evaluations = expanded;
  IterationStats stats;
  stats.iteration = 0;
  stats.best_fitness = result.fitness;
  stats.mean_fitness = result.fitness;
  stats.evaluations = expanded;
  stats.elapsed = absl::Now() - started;
  stats.feasible = result.found;
  observer.OnIteration(stats);
  result.convergence.push_back(stats);
  return result;
}

SearchResult Stopped(StopReason reason) {
  SearchResult result;
  result.stop_reason = reason;
  return result;
}

// The path through the cell centres, beginning at the exact start and ending at the exact goal
// when they are not cell centres themselves (each lies in the first or last cell).
Path GridPathFromTo(const OccupancyGrid& grid, const std::vector<Cell>& cells, const Point3& start,
                    const Point3& goal) {
  Path centres = CellPathToWorld(grid, cells);
  if (centres.empty()) return centres;
  const Point3 start2(start.x(), start.y(), 0.0), goal2(goal.x(), goal.y(), 0.0);
  Path path;
  path.reserve(centres.size() + 2);
  if (start2 != centres.front()) path.push_back(start2);
  for (const Point3& p : centres) path.push_back(p);
  if (goal2 != path.back()) path.push_back(goal2);
  return path;
}

GridSearchOptions GridOptions(const ParamSet& params) {
  GridSearchOptions options;
  options.connectivity =
      params.Enum("connectivity") == "4" ? GridConnectivity::kFour : GridConnectivity::kEight;
  options.allow_corner_cutting = params.Bool("allow_corner_cutting");
  return options;
}

absl::StatusOr<const OccupancyGrid*> RequireGrid(const Problem& problem, const char* id) {
  const OccupancyGrid* grid = problem.map != nullptr ? problem.map->grid() : nullptr;
  if (grid == nullptr) {
    return absl::FailedPreconditionError(
        absl::StrCat("algorithm '", id, "' plans on occupancy-grid maps only"));
  }
  return grid;
}

// The search runs between cells: the start and goal cells must be usable.
absl::Status CheckEndCell(const OccupancyGrid& grid, Cell cell, double clearance,
                          const char* field) {
  if (CellUsable(grid, cell, clearance)) return absl::OkStatus();
  if (!grid.InBounds(cell)) {
    return absl::FailedPreconditionError(
        absl::StrCat(field, " cell ", cell.x, ",", cell.y, " is outside the grid"));
  }
  if (grid.IsBlocked(cell)) {
    return absl::FailedPreconditionError(
        absl::StrCat(field, " cell ", cell.x, ",", cell.y, " is blocked"));
  }
  return absl::FailedPreconditionError(absl::StrCat(
      field, " cell ", cell.x, ",", cell.y, ": its centre is closer than the clearance ", clearance,
      " to a blocked cell (clearance there: ", CellCenterClearance(grid, cell), ")"));
}

// A* (heuristic), Dijkstra (none) or Theta* (any-angle) over the grid's cells.
class GridSearchPlanner final : public Planner {
 public:
  GridSearchPlanner(const char* id, GridSearchOptions options, bool any_angle)
      : id_(id), options_(std::move(options)), any_angle_(any_angle) {}

  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override {
    absl::StatusOr<const OccupancyGrid*> grid = RequireGrid(problem, id_);
    if (!grid.ok()) return grid.status();
    if (StopReason reason = stop.Check(0); reason != StopReason::kNone) return Stopped(reason);
    const absl::Time started = absl::Now();
    GridSearchOptions options = options_;
    options.clearance = problem.clearance;
    options.stop = &stop;
    const Cell from = (*grid)->CellAt(problem.start.head<2>());
    const Cell to = (*grid)->CellAt(problem.goal.head<2>());
    if (absl::Status s = CheckEndCell(**grid, from, problem.clearance, "start"); !s.ok()) return s;
    if (absl::Status s = CheckEndCell(**grid, to, problem.clearance, "goal"); !s.ok()) return s;
    const GridSearchResult search =
        any_angle_ ? ThetaStar(**grid, GridCollisionChecker(**grid), from, to, options, &context_)
                   : SearchGrid(**grid, from, to, options, &context_);
    if (search.stopped) return Stopped(stop.Check(0));
    return FinishSearch(GridPathFromTo(**grid, search.cells, problem.start, problem.goal),
                        search.expanded, started, observer);
  }

 private:
  const char* id_;
  GridSearchOptions options_;
  bool any_angle_;
  GridSearchContext context_;
};

// Visibility graph + shortest path on a shape world.
class VisibilityGraphPlanner final : public Planner {
 public:
  explicit VisibilityGraphPlanner(double circle_tolerance) : circle_tolerance_(circle_tolerance) {}

  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override {
    const ShapeWorld* world = problem.map != nullptr ? problem.map->world() : nullptr;
    if (world == nullptr) {
      return absl::FailedPreconditionError(
          "algorithm 'visibility-graph' plans on shape-world maps only");
    }
    if (StopReason reason = stop.Check(0); reason != StopReason::kNone) return Stopped(reason);
    const absl::Time started = absl::Now();
    absl::StatusOr<Path> path =
        ShortestPathVisibility(*world, problem.start.head<2>(), problem.goal.head<2>(),
                               problem.clearance, circle_tolerance_);
    if (absl::IsNotFound(path.status())) return FinishSearch({}, 0, started, observer);
    if (!path.ok()) return path.status();
    return FinishSearch(*std::move(path), 0, started, observer);
  }

 private:
  double circle_tolerance_;
};

std::vector<ParamSpec> GridMoveParams() {
  return {
      ParamSpec::Enum("connectivity", "8", {"8", "4"},
                      "neighbours of a cell: 8 (with diagonals, octile costs) or 4"),
      ParamSpec::Bool("allow_corner_cutting", false,
                      "allow a diagonal step past a blocked orthogonal neighbour"),
  };
}

PlannerInfo GridSearchInfo(const char* id, std::string description, bool use_heuristic,
                           bool any_angle) {
  PlannerInfo info;
  info.id = id;
  info.description = std::move(description);
  info.seed_paper = "";
  info.encoding = Encoding::kExact;
  info.map_kinds = {MapKind::kOccupancyGrid};
  info.params = GridMoveParams();
  info.factory = [id, use_heuristic,
                  any_angle](const ParamSet& params) -> std::unique_ptr<Planner> {
    GridSearchOptions options = GridOptions(params);
    options.use_heuristic = use_heuristic;
    return std::make_unique<GridSearchPlanner>(id, options, any_angle);
  };
  return info;
}

PlannerInfo VisibilityGraphInfo() {
  PlannerInfo info;
  info.id = "visibility-graph";
  info.description =
      "Visibility graph and shortest path on a shape world: the exact Euclidean shortest path "
      "among the obstacles grown by the clearance. Circles and grown corners become "
      "circumscribed polygons whose vertices lie at most circle_tolerance beyond the true "
      "boundary, so the path is optimal up to that tolerance per arc and always keeps the "
      "clearance. One iteration.";
  info.seed_paper = "";
  info.encoding = Encoding::kExact;
  info.map_kinds = {MapKind::kShapeWorld};
  info.params = {ParamSpec::Double("circle_tolerance", 0.01, 1e-6, std::nullopt, "map units",
                                   "largest distance between a circle (or grown corner) and "
                                   "the polygon that replaces it")
                     .Ours()};
  info.factory = [](const ParamSet& params) -> std::unique_ptr<Planner> {
    return std::make_unique<VisibilityGraphPlanner>(params.Double("circle_tolerance"));
  };
  return info;
}

void MustRegister(Registry& registry, PlannerInfo info) {
  const absl::Status status = registry.Register(std::move(info));
  // Registration of our own planners fails only on a programming error.
  if (!status.ok()) std::abort();
}

}  // namespace

void RegisterExactPlanners(Registry& registry) {
  MustRegister(registry,
               GridSearchInfo("astar",
                              "A* over the cells of an occupancy grid: 8- or 4-connected, octile "
                              "step costs (1 and sqrt(2) cells), no corner cutting by default, "
                              "octile heuristic. The exact shortest grid path through cell "
                              "centres; with a clearance, only cells whose centre keeps it from "
                              "every blocked cell square are used. One iteration.",
                              true, false));
  MustRegister(registry, GridSearchInfo("dijkstra",
                                        "Dijkstra over the cells of an occupancy grid, with the "
                                        "same moves and costs as astar but no heuristic: the "
                                        "same optimal length, a reference for astar. One "
                                        "iteration.",
                                        false, false));
  MustRegister(
      registry,
      GridSearchInfo("theta-star",
                     "Theta* (Nash et al. 2007): A* over the grid's cells where a cell "
                     "may link straight to its parent's parent when the segment between "
                     "their centres is collision-free, giving any-angle paths usually shorter "
                     "than grid paths (not guaranteed optimal). Moves and clearance as "
                     "in astar. One iteration.",
                     true, true));
  MustRegister(registry, VisibilityGraphInfo());
  MustRegister(registry, TerrainLatticeInfo());
}

}  // namespace swarmplan
