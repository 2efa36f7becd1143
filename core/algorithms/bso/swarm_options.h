#pragma once

#include <functional>
#include <string>

#include "absl/status/statusor.h"
#include "core/algorithms/baselines/ba.h"
#include "core/algorithms/bso/beetle_swarm.h"
#include "core/params.h"

namespace swarmplan {

// The optimiser options of the waypoint swarm planners, built from their resolved parameters.
// The planners and anything that runs their optimisers on other objectives (the test functions
// of bench/papers) use these, so both run the very same settings.

// `positions`, the PositionBound parameter of every waypoint swarm planner.
ParamSpec PositionsParam();

// bso (aem = false), aem-bso and aem-bso-linear (aem = true; they differ in `inertia`).
BeetleSwarmOptions BeetleSwarmOptionsFromParams(bool aem, const ParamSet& params);
// pso: the beetle swarm loop without antennae, linear inertia.
BeetleSwarmOptions PsoOptionsFromParams(const ParamSet& params);
// ba.
BatOptions BatOptionsFromParams(const ParamSet& params);

// One of those optimisers, ready to run on any box-bounded objective.
using SwarmOptimiser = std::function<SearchOutcome(Objective& objective, int t_max, Rng& rng,
                                                   const StopToken& stop, Observer& observer)>;

// The optimiser of the planner `planner_id` (bso, aem-bso, aem-bso-linear, pso, ba) with the
// planner's resolved parameters; NOT_FOUND for any other id.
absl::StatusOr<SwarmOptimiser> SwarmOptimiserFor(const std::string& planner_id,
                                                 const ParamSet& params);

}  // namespace swarmplan
