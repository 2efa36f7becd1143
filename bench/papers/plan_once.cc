#include "bench/papers/plan_once.h"

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

}  // namespace swarmplan::bench
