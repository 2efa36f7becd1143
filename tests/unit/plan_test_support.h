#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "core/registry.h"
#include "core/run.h"

namespace swarmplan::testing {

class NullObserver final : public Observer {
 public:
  void OnIteration(const IterationStats&) override {}
};

// RunPlan of the default registry's `algorithm` from start to goal (world coordinates, z = 0).
inline absl::StatusOr<PlanResult> PlanOnMap(const std::string& algorithm, const MapPtr& map,
                                            const Point2& start, const Point2& goal,
                                            double clearance = 0.0,
                                            const ParamValues& params = {}) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.params = params;
  request.problem.map = map;
  request.problem.start = Point3(start.x(), start.y(), 0);
  request.problem.goal = Point3(goal.x(), goal.y(), 0);
  request.problem.clearance = clearance;
  NullObserver observer;
  return RunPlan(DefaultRegistry(), request, StopToken(), observer);
}

}  // namespace swarmplan::testing
