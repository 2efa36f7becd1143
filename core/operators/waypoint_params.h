#pragma once

#include <string>
#include <vector>

#include "core/operators/path_search_planner.h"
#include "core/operators/waypoint_objective.h"
#include "core/params.h"

namespace swarmplan {

// The parameters every 2D waypoint planner shares: iterations, waypoints, interpolation,
// samples, penalty (M), d_safe. `waypoints` is the default waypoint count.
std::vector<ParamSpec> WaypointParams(int default_iterations, int default_waypoints);
WaypointFitnessOptions WaypointFitnessFrom(const ParamSet& params);

// Builds a WaypointObjective for the problem's 2D map.
PathSearchPlanner::ObjectiveFactory WaypointObjectiveFactory(const WaypointFitnessOptions& options);

// A parameter's value when declared by the planner, else `fallback`.
double DoubleOr(const ParamSet& params, const std::string& name, double fallback);
int64_t IntOr(const ParamSet& params, const std::string& name, int64_t fallback);
bool BoolOr(const ParamSet& params, const std::string& name, bool fallback);

// Appends `more` to `specs`.
void AppendParams(std::vector<ParamSpec>& specs, const std::vector<ParamSpec>& more);

}  // namespace swarmplan
