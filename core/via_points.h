#pragma once

#include <vector>

#include "absl/status/statusor.h"
#include "core/optimum.h"
#include "core/planner.h"
#include "core/run.h"
#include "core/stop_token.h"

namespace swarmplan {

// The legs of a request with via-points: start -> via_points[0] -> ... -> goal, each the
// request's problem between two consecutive points.
std::vector<Problem> LegProblems(const PlanRequest& request);

// RunPlan for a request with via-points (validated): each leg planned in turn by RunPlan as its
// own request, with seed + k for leg k (the seed picked once when 0), the time left divided
// evenly among the legs left and the iteration cap per leg; no alternatives. The result joins
// the legs' paths (each via-point once), sums their fitness, iterations and evaluations, and
// streams and keeps one convergence: the legs one after the other, iterations counted on, each
// leg's best and mean plus the fitness of the legs before it. It stops at the first leg without
// a path: the result is then not found and its paths end at the last via-point reached. The
// objective and the timed path are those of the joined final path.
absl::StatusOr<PlanResult> RunThroughViaPoints(const Registry& registry, const PlanRequest& request,
                                               const StopToken& stop, Observer& observer);

// The optimum through the via-points: the sum of the legs' optima, known when every leg's is
// (a single leg's as it is).
Optimum CombineLegOptima(const std::vector<Optimum>& legs);

}  // namespace swarmplan
