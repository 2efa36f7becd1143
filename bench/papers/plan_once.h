#pragma once

#include <cstdint>
#include <string>

#include "absl/status/statusor.h"
#include "core/map/map.h"
#include "core/params.h"
#include "core/run.h"

namespace swarmplan::bench {

// One planner configuration of a reproduction: the registered planner, its parameters (the
// rest keep their defaults) and what RunPlan does around it.
struct PlanSpec {
  std::string algorithm;
  ParamValues params;
  std::string smoothing = "none";
  int max_iterations = 0;  // 0: the planner's default
  double clearance = 0.0;
};

// Plans once through RunPlan with the default registry, as the server would; the convergence
// record is kept in the result.
absl::StatusOr<PlanResult> PlanOnce(const PlanSpec& spec, const MapPtr& map, const Point3& start,
                                    const Point3& goal, uint64_t seed);

// The check every experiment makes on every plan: OK when no path was found, or when the found
// path is collision-free (RunPlan's exact check) and runs from `start` to `goal` (within
// `tolerance`). Anything else is a planner bug: INTERNAL, prefixed with `what`.
absl::Status CheckFoundPath(const PlanResult& result, const Point3& start, const Point3& goal,
                            const std::string& what, double tolerance = 1e-9);

}  // namespace swarmplan::bench
