#include "bench/papers/plan_once.h"

#include "absl/strings/str_cat.h"
#include "core/planner.h"
#include "core/registry.h"
#include "core/stop_token.h"

namespace swarmplan::bench {

absl::StatusOr<PlanResult> PlanOnce(const PlanSpec& spec, const MapPtr& map, const Point3& start,
                                    const Point3& goal, uint64_t seed) {
  PlanRequest request;
  request.algorithm = spec.algorithm;
  request.params = spec.params;
  request.smoothing = spec.smoothing;
  request.problem.map = map;
  request.problem.start = start;
  request.problem.goal = goal;
  request.problem.clearance = spec.clearance;
  request.problem.limits.max_iterations = spec.max_iterations;
  request.problem.seed = seed;
  NullObserver observer;
  return RunPlan(DefaultRegistry(), request, StopToken(), observer);
}

absl::Status CheckFoundPath(const PlanResult& result, const Point3& start, const Point3& goal,
                            const std::string& what, double tolerance) {
  if (!result.found) return absl::OkStatus();
  if (!result.raw_metrics.collision_free) {
    return absl::InternalError(absl::StrCat(what, ": the found path is not collision-free"));
  }
  const Path& path = result.raw_path;
  if (path.size() < 2 || (path.front() - start).norm() > tolerance ||
      (path.back() - goal).norm() > tolerance) {
    return absl::InternalError(
        absl::StrCat(what, ": the found path does not run from start to goal"));
  }
  return absl::OkStatus();
}

}  // namespace swarmplan::bench
