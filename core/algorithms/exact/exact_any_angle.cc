#include "core/algorithms/exact/exact_any_angle.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
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
#include "core/geometry/collision.h"
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

// Portals: an endpoint that keeps the clearance but lies in a cell the inflated grid blocks
// (a cell beside a wall is blocked for every clearance > 0) joins the search at the nearest
// usable point within kPortalReach cells, reached by a segment that keeps the clearance by the
// map's exact checker. Rings of kPortalDirections points every kPortalStep cells.
constexpr double kPortalReach = 3.0;
constexpr double kPortalStep = 0.25;
constexpr int kPortalDirections = 32;

// The point the search starts (or ends) at for endpoint `local` (grid coordinates): `local`
// itself when the planning grid can use it, else the portal nearest to it (ties: the one
// nearer `toward`), else none.
std::optional<Point2> SearchPoint(const OccupancyGrid& planning, const CollisionChecker& exact,
                                  const OccupancyGrid& grid, const Point2& local,
                                  const Point2& toward, double clearance) {
  const GridCollisionChecker usable(planning);
  if (usable.TraversalFree(local, local)) return local;
  if (clearance <= 0) return std::nullopt;
  const auto world = [&](const Point2& p) {
    const Point2 w = grid.origin() + p * grid.resolution();
    return Point3(w.x(), w.y(), 0.0);
  };
  for (double r = kPortalStep; r <= kPortalReach + 1e-9; r += kPortalStep) {
    std::optional<Point2> best;
    double best_score = 0.0;
    for (int i = 0; i < kPortalDirections; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / kPortalDirections;
      const Point2 q = local + r * Point2(std::cos(angle), std::sin(angle));
      if (!usable.TraversalFree(q, q) || !exact.SegmentFree(world(local), world(q), clearance)) {
        continue;
      }
      const double score = (toward - q).norm();
      if (!best || score < best_score) {
        best = q;
        best_score = score;
      }
    }
    if (best) return best;
  }
  return std::nullopt;
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
    const std::unique_ptr<const CollisionChecker> exact = MakeCollisionChecker(*problem.map);
    const std::optional<Point2> from =
        SearchPoint(planning, *exact, *grid, start, goal, problem.clearance);
    if (!from) return CheckEndPoint(planning, start, problem.start, problem.clearance, "start");
    const std::optional<Point2> to =
        SearchPoint(planning, *exact, *grid, goal, start, problem.clearance);
    if (!to) return CheckEndPoint(planning, goal, problem.goal, problem.clearance, "goal");
    const AnyAngleSearchResult search = AnyAngleSearch(*cached, *from, *to, &stop);
    if (search.stopped) return StoppedExactSearch(stop.Check(0));
    if (!search.found) return FinishExactSearch({}, search.expanded, started, observer);
    absl::StatusOr<std::vector<Point2>> offset =
        OffsetTautPath(planning, search.vertices, kCornerOffset);
    if (!offset.ok()) return offset.status();
    Path path;
    path.reserve(offset->size() + 2);
    for (const Point2& p : *offset) {
      const Point2 w = grid->origin() + p * grid->resolution();
      path.emplace_back(w.x(), w.y(), 0.0);
    }
    // The ends are the requested points exactly, not their round trip through grid units; a
    // portal stays as the vertex after (before) them.
    const Point3 first(problem.start.x(), problem.start.y(), 0.0);
    const Point3 last(problem.goal.x(), problem.goal.y(), 0.0);
    if (*from == start) {
      path.front() = first;
    } else {
      path.insert(path.begin(), first);
    }
    if (*to == goal) {
      path.back() = last;
    } else {
      path.push_back(last);
    }
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
      "optimum with that clearance. A start or goal that keeps the clearance in a cell the "
      "inflated grid blocks (any cell beside a wall) joins the search at the nearest usable "
      "point within 3 cells, by a segment that keeps the clearance. One iteration.";
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
