#include "core/algorithms/exact/exact_any_angle.h"

#include <algorithm>
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
#include "core/algorithms/exact/clearance_repair.h"
#include "core/algorithms/exact/exact_search_result.h"
#include "core/algorithms/exact/taut_path_offset.h"
#include "core/geometry/collision.h"
#include "core/geometry/grid_collision.h"

namespace swarmplan {
namespace {

constexpr const char* kId = "exact-any-angle";
// How far (cells, per axis) the path's vertices move off the corners they wrap.
constexpr double kCornerOffset = 1e-7;

// Why the start or goal cannot join the search: it lies outside the map, in or on a blocked
// cell, closer than the clearance to one, or no usable point near it can be reached.
absl::Status EndPointError(const OccupancyGrid& planning, const CollisionChecker& exact,
                           const Point2& local, const Point3& world, double clearance,
                           const char* field) {
  const std::string where = absl::StrCat(field, " (", world.x(), ", ", world.y(), ")");
  if (local.x() < 0 || local.y() < 0 || local.x() > planning.width() ||
      local.y() > planning.height()) {
    return absl::FailedPreconditionError(absl::StrCat(where, " is outside the grid"));
  }
  if (clearance <= 0) {
    const Cell cell = planning.CellAt(world.head<2>());
    return absl::FailedPreconditionError(absl::StrCat(
        where, " lies in or on the border of a blocked cell near cell ", cell.x, ",", cell.y));
  }
  const double kept = exact.Clearance(world);
  if (kept < clearance) {
    return absl::FailedPreconditionError(
        absl::StrCat(where, " lies ", std::max(kept, 0.0),
                     " from the nearest blocked cell, closer than the clearance ", clearance));
  }
  return absl::FailedPreconditionError(
      absl::StrCat(where, " keeps the clearance ", clearance, " but no point within ",
                   "3 cells of it where the whole neighbourhood does can be reached"));
}

// Portals: an endpoint that keeps the clearance but lies on or in a cell the planning grid
// blocks (on the boundary of the region that keeps the clearance, or within the margin) joins
// the search at the nearest usable point within kPortalReach map cells plus the margin, reached
// by a segment that keeps the clearance by the map's exact checker. Rings of kPortalDirections
// points every kPortalStep map cells.
constexpr double kPortalReach = 3.0;
constexpr double kPortalStep = 0.25;
constexpr int kPortalDirections = 32;

// The point the search starts (or ends) at for endpoint `local` (planning-grid coordinates):
// `local` itself when the planning grid can use it, else the portal nearest to it (ties: the
// one nearer `toward`) within `reach` map cells, else none. `scale`: planning cells per map
// cell. `subdivided`: whether the planning grid is a clearance grid (else no portals).
std::optional<Point2> SearchPoint(const OccupancyGrid& planning, const CollisionChecker& exact,
                                  const Point2& local, const Point2& toward, double clearance,
                                  bool subdivided, double reach, double scale) {
  const GridCollisionChecker usable(planning);
  if (usable.TraversalFree(local, local)) return local;
  if (!subdivided) return std::nullopt;
  const auto world = [&](const Point2& p) {
    const Point2 w = planning.origin() + p * planning.resolution();
    return Point3(w.x(), w.y(), 0.0);
  };
  for (double r = kPortalStep; r <= reach + 1e-9; r += kPortalStep) {
    std::optional<Point2> best;
    double best_score = 0.0;
    for (int i = 0; i < kPortalDirections; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / kPortalDirections;
      const Point2 q = local + r * scale * Point2(std::cos(angle), std::sin(angle));
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

// The shortest path on one planning grid between the problem's ends.
struct PlanningGridPath {
  absl::Status status;  // an end the grid cannot use
  bool stopped = false;
  bool found = false;
  int64_t expanded = 0;
  // World points: the requested ends exactly (not their round trip through grid units), a
  // portal as the vertex after (before) them, and between them the search's vertices, moved
  // off the corners they wrap when `offset` is set.
  std::vector<Point2> vertices;
  bool start_portal = false;  // vertices[1] is the start's portal
  bool goal_portal = false;   // vertices[size - 2] is the goal's portal
};

// `margin` (world units): the planning grid keeps the problem's clearance plus the margin; the
// ends need only keep the clearance, joined to the grid by portals.
PlanningGridPath SearchPlanningGrid(const AnyAngleGrid& cached, double map_resolution,
                                    const CollisionChecker& exact, const Problem& problem,
                                    double margin, const StopToken& stop, bool offset) {
  PlanningGridPath result;
  const OccupancyGrid& planning = cached.planning_grid();
  const double inv_resolution = 1.0 / planning.resolution();
  const double scale = map_resolution * inv_resolution;
  const bool subdivided = problem.clearance + margin > 0;
  const double reach = kPortalReach + margin / map_resolution;
  const Point2 start = (problem.start.head<2>() - planning.origin()) * inv_resolution;
  const Point2 goal = (problem.goal.head<2>() - planning.origin()) * inv_resolution;
  const std::optional<Point2> from =
      SearchPoint(planning, exact, start, goal, problem.clearance, subdivided, reach, scale);
  if (!from) {
    result.status =
        EndPointError(planning, exact, start, problem.start, problem.clearance, "start");
    return result;
  }
  const std::optional<Point2> to =
      SearchPoint(planning, exact, goal, start, problem.clearance, subdivided, reach, scale);
  if (!to) {
    result.status = EndPointError(planning, exact, goal, problem.goal, problem.clearance, "goal");
    return result;
  }
  const AnyAngleSearchResult search = AnyAngleSearch(cached, *from, *to, &stop);
  result.stopped = search.stopped;
  result.found = search.found;
  result.expanded = search.expanded;
  if (!search.found) return result;
  std::vector<Point2> local = search.vertices;
  if (offset) {
    absl::StatusOr<std::vector<Point2>> moved =
        OffsetTautPath(planning, search.vertices, kCornerOffset);
    if (!moved.ok()) {
      result.status = moved.status();
      return result;
    }
    local = *std::move(moved);
  }
  result.vertices.reserve(local.size() + 2);
  for (const Point2& p : local) {
    result.vertices.push_back(planning.origin() + p * planning.resolution());
  }
  result.start_portal = *from != start;
  result.goal_portal = *to != goal;
  if (result.start_portal) result.vertices.insert(result.vertices.begin(), Point2::Zero());
  if (result.goal_portal) result.vertices.push_back(Point2::Zero());
  result.vertices.front() = problem.start.head<2>();
  result.vertices.back() = problem.goal.head<2>();
  return result;
}

double PolylineLength(const std::vector<Point2>& points) {
  double length = 0.0;
  for (size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

class ExactAnyAnglePlanner final : public Planner {
 public:
  ExactAnyAnglePlanner(ClearanceBound bound, double margin) : bound_(bound), margin_(margin) {}

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
    const std::unique_ptr<const CollisionChecker> exact = MakeCollisionChecker(*problem.map);
    const double kept = problem.clearance + margin_;
    const auto search = [&](ClearanceBound bound) {
      return SearchPlanningGrid(*AnyAngleGridFor(*problem.map, kept, bound), grid->resolution(),
                                *exact, problem, margin_, stop,
                                /*offset=*/bound == ClearanceBound::kUpper);
    };
    PlanningGridPath best = search(bound_);
    if (best.stopped) return StoppedExactSearch(stop.Check(0));
    const bool repair = kept > 0 && bound_ == ClearanceBound::kUpper;
    if (!best.status.ok() && !repair) return best.status;
    int64_t expanded = best.expanded;
    if (repair) {
      // The upper grid misses where the clearance bends around a corner between sub-cells, and
      // passages where only the corners of its sub-cells meet: the lower bound's path, moved
      // off the obstacles until it keeps the clearance, often passes there.
      PlanningGridPath lower = search(ClearanceBound::kLower);
      if (lower.stopped) return StoppedExactSearch(stop.Check(0));
      expanded += lower.expanded;
      if (!best.status.ok() && !lower.found) return best.status;
      std::optional<std::vector<Point2>> repaired;
      if (lower.found) repaired = RepairKeeping(*grid, *exact, lower, kept);
      if (repaired && (!best.found || !best.status.ok() ||
                       PolylineLength(*repaired) < PolylineLength(best.vertices))) {
        best.status = absl::OkStatus();
        best.found = true;
        best.vertices = *std::move(repaired);
      }
      if (!best.status.ok()) return best.status;
    }
    if (!best.found) return FinishExactSearch({}, expanded, started, observer);
    Path path;
    path.reserve(best.vertices.size());
    for (const Point2& p : best.vertices) path.emplace_back(p.x(), p.y(), 0.0);
    return FinishExactSearch(std::move(path), expanded, started, observer);
  }

 private:
  // The lower bound's path between its portals made to keep `kept`; the segments to the ends
  // keep the problem's clearance already (SearchPoint).
  static std::optional<std::vector<Point2>> RepairKeeping(const OccupancyGrid& grid,
                                                          const CollisionChecker& exact,
                                                          const PlanningGridPath& lower,
                                                          double kept) {
    const std::vector<Point2>& all = lower.vertices;
    const auto first = all.begin() + (lower.start_portal ? 1 : 0);
    const auto last = all.end() - (lower.goal_portal ? 1 : 0);
    std::optional<std::vector<Point2>> inner =
        RepairToClearance(grid, exact, std::vector<Point2>(first, last), kept);
    if (!inner) return std::nullopt;
    if (lower.start_portal) inner->insert(inner->begin(), all.front());
    if (lower.goal_portal) inner->push_back(all.back());
    return inner;
  }

  ClearanceBound bound_;
  double margin_;
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
      "squeezes between two blocked cells that touch at a corner. With a clearance it brackets "
      "the optimum on sub-cells (the map's cells split into 4 x 4; 2 x 2 on grids over 512 x 512 "
      "cells, 1 x 1 over 1024 x 1024): the upper grid keeps the sub-cells whose squares keep "
      "the clearance from every blocked cell (its path keeps it), the lower grid blocks only "
      "those that lie wholly closer (its length, bound=lower, is never beaten by a path that "
      "keeps the clearance). The path returned is the shorter of the upper grid's and the lower "
      "grid's path moved off the walls until it keeps the clearance with a margin of 1e-3 of it "
      "(bench/results/exact-yardsticks.md measures it against the lower bound and theta-star). "
      "Where the clearance fits only with no margin at all (a one-cell door at clearance 0.5) "
      "the path returned passes only if it can go straight through. A start or goal on the "
      "boundary of the region that keeps the clearance joins the search at the nearest usable "
      "point within 3 cells, by a segment that keeps the clearance. One iteration.";
  info.seed_paper = citations::kAnya;
  info.encoding = Encoding::kExact;
  info.map_kinds = {MapKind::kOccupancyGrid};
  info.params = {ParamSpec::Enum(
      "bound", "upper", {"upper", "lower"},
      "with a clearance: upper plans on the sub-cells that keep it (the path keeps the "
      "clearance); lower on those not wholly within it of a blocked cell, a length no path that "
      "keeps the clearance beats (the path may come closer: a yardstick, not a plan)")};
  info.params.push_back(
      ParamSpec::Double("margin", 0.0, 0.0, std::nullopt, "map units",
                        "plan keeping the clearance plus this margin; the start and goal need "
                        "keep only the clearance, joined to the path by a straight segment")
          .Ours());
  info.factory = [](const ParamSet& params) -> std::unique_ptr<Planner> {
    return std::make_unique<ExactAnyAnglePlanner>(
        params.Enum("bound") == "lower" ? ClearanceBound::kLower : ClearanceBound::kUpper,
        params.Double("margin"));
  };
  return info;
}

}  // namespace swarmplan
