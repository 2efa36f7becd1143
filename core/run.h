#pragma once

#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "core/fitness/fleet_objective.h"
#include "core/optimum.h"
#include "core/path_metrics.h"
#include "core/planner.h"
#include "core/registry.h"
#include "core/timing/timed_path.h"

namespace swarmplan {

// A plan as a client asks for it: the algorithm by id, its raw parameters, the problem (a seed
// of 0 means "pick one and report it"), the smoothing to apply to the raw path and the vehicle
// whose limits time the final path.
struct PlanRequest {
  std::string algorithm;
  ParamValues params;
  Problem problem;
  std::string smoothing = "none";  // "none", or a method of SmoothingMethods()
  VehicleLimits vehicle;           // timed() or not: whether the result has a timed_path
  // Points the path passes through, in order, between start and goal (at most kMaxViaPoints,
  // each inside the map and keeping the clearance). Each leg is planned as its own problem
  // (RunThroughViaPoints).
  std::vector<Point3> via_points;
};

// Everything a plan returns, the same whatever the planner.
struct PlanResult {
  std::string algorithm;
  bool found = false;
  Path raw_path;
  Path smoothed_path;  // equals raw_path when smoothing is "none"
  PathMetrics raw_metrics;
  PathMetrics smoothed_metrics;
  std::string smoothing;
  bool smoothing_collision_free = true;
  double fitness = 0.0;
  int iterations = 0;
  int64_t evaluations = 0;
  int best_iteration = 0;
  StopReason stop_reason = StopReason::kNone;
  absl::Duration wall_time;
  absl::Duration cpu_time;
  uint64_t seed = 0;
  ParamValues resolved_params;
  std::vector<IterationStats> convergence;
  // On 2D maps, each term of the problem's fleet objective for the final path (the smoothed
  // one, or the raw one when smoothing lost the clearance), and for the best seed path the
  // planner started from after the same smoothing, when it had one. When that seed is better by
  // the objective than the planner's path after the smoothing, or when the smoothing keeps the
  // seed clear and within the turning radius but not the planner's path, the seed is the
  // result (raw and smoothed path, its objective as `fitness`, best_iteration 0).
  std::optional<FleetTerms> objective;
  std::optional<FleetTerms> seed_objective;
  // With a timed vehicle and a path: the final path (the smoothed one, or the raw one when
  // smoothing lost the clearance) timed within the vehicle's limits (TimePath).
  std::optional<TimedPath> timed_path;
  // With via-points: how many of them the path reaches, in order (all when found; when a leg
  // finds no path, the path ends at the last via-point reached), and each planned leg, the
  // failed one last.
  int via_points_reached = 0;
  struct Leg {
    bool found = false;
    PathMetrics metrics;  // of the leg's final path (smoothed, or raw when smoothing lost it)
    double fitness = 0.0;
    int iterations = 0;
  };
  std::vector<Leg> legs;
  // The exact optimum of the problem and the final path's cost over the optimum's (PlanCost:
  // the length on 2D maps; of the smoothed path, or of the raw one when smoothing lost the
  // clearance; 0 when the optimum is not known or no path was found). RunPlan leaves them
  // empty: see SetOptimum.
  Optimum optimum;
  double optimality_ratio = 0.0;
  // Paths in other corridors when the problem asked for alternatives (raw, not smoothed), best
  // first; optimality_ratio set by SetOptimum like the result's.
  struct Alternative {
    Path path;
    PathMetrics metrics;
    double fitness = 0.0;
    double optimality_ratio = 0.0;
  };
  std::vector<Alternative> alternatives;
};

// Checks the request (known algorithm, parameters, map kind, start and goal inside the map and
// clear of obstacles, and the planner's own Planner::CheckProblem), then runs the planner
// under `stop` (tightened by the problem's limits), smooths and evaluates the path. Errors:
// INVALID_ARGUMENT (parameters, smoothing), NOT_FOUND (algorithm), FAILED_PRECONDITION (map
// kind, start or goal blocked or outside, or not usable by the planner, e.g. in a blocked cell
// of its raster: the message names the algorithm and the cell).
absl::StatusOr<PlanResult> RunPlan(const Registry& registry, const PlanRequest& request,
                                   const StopToken& stop, Observer& observer);

// Records the problem's exact optimum in a result and measures the final path against it.
void SetOptimum(const Map& map, Optimum optimum, PlanResult& result);

// The checks RunPlan makes before it plans, for callers that want to reject a request early.
absl::Status ValidatePlanRequest(const Registry& registry, const PlanRequest& request);

}  // namespace swarmplan
