#include "core/algorithms/exact/exact_any_angle.h"

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "core/algorithms/citations.h"
#include "core/algorithms/exact/any_angle_grid.h"
#include "core/algorithms/exact/any_angle_search.h"
#include "core/algorithms/exact/exact_search_result.h"
#include "core/algorithms/exact/taut_path_offset.h"
#include "core/geometry/grid_collision.h"

namespace swarmplan {
namespace {

constexpr const char* kId = "exact-any-angle";
// How far (cells, per axis) the path's vertices move off the corners they wrap.
constexpr double kCornerOffset = 1e-7;

// The start or goal must lie in the map and touch no blocked cell of the planning grid.
absl::Status CheckEndPoint(const OccupancyGrid& planning, const Point2& local, const Point3& world,
                           double clearance, const char* field) {
  const GridCollisionChecker checker(planning);
  if (checker.TraversalFree(local, local)) return absl::OkStatus();
  const std::string where = absl::StrCat(field, " (", world.x(), ", ", world.y(), ")");
  if (local.x() < 0 || local.y() < 0 || local.x() > planning.width() ||
      local.y() > planning.height()) {
    return absl::FailedPreconditionError(absl::StrCat(where, " is outside the grid"));
  }
  const Cell cell = planning.CellAt(world.head<2>());
  if (clearance > 0) {
    return absl::FailedPreconditionError(absl::StrCat(
        where, " touches cell ", cell.x, ",", cell.y, " (or a neighbour) of the grid inflated by ",
        "the clearance ", clearance, ": ", kId,
        " plans on cells whose squares keep the clearance from every blocked cell"));
  }
  return absl::FailedPreconditionError(absl::StrCat(
      where, " lies in or on the border of a blocked cell near cell ", cell.x, ",", cell.y));
}

class ExactAnyAnglePlanner final : public Planner {
 public:
  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override {
    const OccupancyGrid* grid = problem.map != nullptr ? problem.map->grid() : nullptr;
    if (grid == nullptr) {
      return absl::FailedPreconditionError(
          absl::StrCat("algorithm '", kId, "' plans on occupancy-grid maps only"));
    }
    if (!std::isfinite(problem.clearance) || problem.clearance < 0) {
      return absl::InvalidArgumentError(
          absl::StrCat("clearance must be a finite number >= 0, got ", problem.clearance));
    }
    if (StopReason reason = stop.Check(0); reason != StopReason::kNone) {
      return StoppedExactSearch(reason);
    }
    const absl::Time started = absl::Now();
    const std::shared_ptr<const AnyAngleGrid> cached =
        AnyAngleGridFor(*problem.map, problem.clearance);
    const OccupancyGrid& planning = cached->planning_grid();
    const double inv_resolution = 1.0 / grid->resolution();
    const Point2 start = (problem.start.head<2>() - grid->origin()) * inv_resolution;
    const Point2 goal = (problem.goal.head<2>() - grid->origin()) * inv_resolution;
    if (absl::Status s = CheckEndPoint(planning, start, problem.start, problem.clearance, "start");
        !s.ok()) {
      return s;
    }
    if (absl::Status s = CheckEndPoint(planning, goal, problem.goal, problem.clearance, "goal");
        !s.ok()) {
      return s;
    }
    const AnyAngleSearchResult search = AnyAngleSearch(*cached, start, goal, &stop);
    if (search.stopped) return StoppedExactSearch(stop.Check(0));
    if (!search.found) return FinishExactSearch({}, search.expanded, started, observer);
    absl::StatusOr<std::vector<Point2>> offset =
        OffsetTautPath(planning, search.vertices, kCornerOffset);
    if (!offset.ok()) return offset.status();
    Path path;
    path.reserve(offset->size());
    for (const Point2& p : *offset) {
      const Point2 w = grid->origin() + p * grid->resolution();
      path.emplace_back(w.x(), w.y(), 0.0);
    }
    // The ends are the requested points exactly, not their round trip through grid units.
    path.front() = Point3(problem.start.x(), problem.start.y(), 0.0);
    path.back() = Point3(problem.goal.x(), problem.goal.y(), 0.0);
    return FinishExactSearch(std::move(path), search.expanded, started, observer);
  }
};

}  // namespace

PlannerInfo ExactAnyAngleInfo() {
  PlannerInfo info;
  info.id = kId;
  info.description =
      "The exact Euclidean shortest path between two arbitrary points of an occupancy grid, "
      "among its blocked cells, by Anya: a search over intervals of grid rows, each seen from "
      "a root (the start or a convex corner), expanded by projecting it through the next row "
      "and by turning around the convex corners on it; optimal, online, no preprocessing. "
      "Ours: the rows through the start and goal join the grid's rows so that the endpoints "
      "need not be cell corners; the free runs of each row are cached with the map; the "
      "optimal path touches the corners it wraps, so its vertices move 1e-7 cells off them and "
      "the path returned is collision-free and within 1e-6 relative of the optimum. It never "
      "squeezes between two blocked cells that touch at a corner. With a clearance it plans on "
      "the grid inflated by the clearance (a cell is blocked when its square comes closer than "
      "the clearance plus 1/16 cell to a blocked square, cached per clearance), so the result "
      "keeps the clearance and is the optimum on the inflated grid: an upper bound of the true "
      "optimum with that clearance. One iteration.";
  info.seed_paper = citations::kAnya;
  info.encoding = Encoding::kExact;
  info.map_kinds = {MapKind::kOccupancyGrid};
  info.params = {};
  info.factory = [](const ParamSet&) -> std::unique_ptr<Planner> {
    return std::make_unique<ExactAnyAnglePlanner>();
  };
  return info;
}

}  // namespace swarmplan
