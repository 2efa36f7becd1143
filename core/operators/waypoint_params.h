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

// How a waypoint planner initialises: `init=seeded` (the service default) searches
// SeededWaypointObjective's corridors of `seeds` seed paths under the problem's fleet
// objective; `init=paper` the paper's WaypointObjective over the map's rectangle, with the
// paper's fitness.
struct WaypointSeeding {
  bool seeded = true;
  int seeds = 3;
  // init=paper: the search box is the map's rectangle shrunk by this on each side (map units).
  double box_inset = 0.0;
};
// `box_inset`, for the waypoint planners whose paper initialisation honours it.
ParamSpec BoxInsetParam();
// `init` and `seeds`, for the planners that offer both initialisations; `seeded_meaning` and
// `paper_meaning` say what each initialisation does in that planner.
std::vector<ParamSpec> SeedingParams(const std::string& seeded_meaning,
                                     const std::string& paper_meaning);
// SeedingParams for the waypoint planners.
std::vector<ParamSpec> WaypointSeedingParams();
// The paper's initialisation when the planner has no `init` parameter; box_inset 0 when it has
// no `box_inset`.
WaypointSeeding WaypointSeedingFrom(const ParamSet& params);

// The most control points of a seeded waypoint path: one per vertex and per segment of a seed
// up to 512 vertices (exact paths with a clearance on 512-cell maps have several hundred, around
// the inflated corners). A seed with more keeps evenly spaced vertices, and with every offset 0
// its path then cuts the corners it dropped.
inline constexpr int kMaxSeededControlPoints = 1024;

// Builds the objective of a waypoint planner for the problem's 2D map.
PathSearchPlanner::ObjectiveFactory WaypointObjectiveFactory(const WaypointFitnessOptions& options,
                                                             const WaypointSeeding& seeding);

// A parameter's value when declared by the planner, else `fallback`.
double DoubleOr(const ParamSet& params, const std::string& name, double fallback);
int64_t IntOr(const ParamSet& params, const std::string& name, int64_t fallback);
bool BoolOr(const ParamSet& params, const std::string& name, bool fallback);

// Appends `more` to `specs`.
void AppendParams(std::vector<ParamSpec>& specs, const std::vector<ParamSpec>& more);

}  // namespace swarmplan
