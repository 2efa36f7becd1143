#pragma once

#include "absl/status/statusor.h"
#include "core/fitness/fleet_objective.h"
#include "core/map/point.h"
#include "core/problem.h"

namespace swarmplan {

// Each term of the problem's fleet objective (its preferences, its hard clearance) for any path
// on its 2D map, read as the fitness engine reads the waypoint planners' paths
// (FitnessEngine::PathTerms). FAILED_PRECONDITION on a terrain.
absl::StatusOr<FleetTerms> EvaluateFleetObjective(const Problem& problem, const Path& path);

}  // namespace swarmplan
