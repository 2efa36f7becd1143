#include "core/optimum.h"

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "core/operators/terrain_path_cost.h"
#include "core/path_metrics.h"

namespace swarmplan {

const char* ExactPlannerFor(MapKind kind) {
  switch (kind) {
    case MapKind::kOccupancyGrid:
      return "exact-any-angle";
    case MapKind::kShapeWorld:
      return "visibility-graph";
    case MapKind::kTerrain:
      return "terrain-lattice";
  }
  return "";
}

Optimum ComputeOptimum(const Registry& registry, const Problem& problem, absl::Duration budget,
                       const StopToken& stop) {
  Optimum optimum;
  if (problem.map == nullptr) {
    optimum.reason = "no map";
    return optimum;
  }
  optimum.planner = ExactPlannerFor(problem.map->kind());
  if (budget <= absl::ZeroDuration()) {
    optimum.reason = "not computed (no time budget for the optimum)";
    return optimum;
  }
  absl::StatusOr<std::unique_ptr<Planner>> planner = registry.Create(optimum.planner, {});
  if (!planner.ok()) {
    optimum.reason = std::string(planner.status().message());
    return optimum;
  }
  Problem exact = problem;
  exact.limits = Limits();
  NullObserver observer;
  const StopToken bounded = stop.WithDeadline(absl::Now() + budget);
  absl::StatusOr<SearchResult> result = (*planner)->Solve(exact, bounded, observer);
  if (!result.ok()) {
    optimum.reason = std::string(result.status().message());
  } else if (result->found) {
    optimum.known = true;
    optimum.length = PathLength(result->path);
    optimum.cost = PlanCost(*problem.map, result->path);
  } else if (result->stop_reason == StopReason::kDeadline) {
    optimum.reason = absl::StrCat("not found within the budget of ", absl::FormatDuration(budget));
  } else if (result->stop_reason == StopReason::kCancelled) {
    optimum.reason = "cancelled";
  } else {
    optimum.reason = "no path exists";
  }
  return optimum;
}

double PlanCost(const Map& map, const Path& path) {
  if (const Terrain* terrain = map.terrain()) return TerrainPathCost(path, terrain->cell_size());
  return PathLength(path);
}

double OptimalityRatio(double cost, const Optimum& optimum) {
  if (!optimum.known || optimum.cost <= 0.0) return 0.0;
  return cost / optimum.cost;
}

}  // namespace swarmplan
