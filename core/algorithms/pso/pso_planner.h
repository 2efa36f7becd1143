#pragma once

#include "core/registry.h"

namespace swarmplan {

// Particle swarm optimisation over spline waypoints, the baseline of the beetle papers: pso.
PlannerInfo PsoInfo();

}  // namespace swarmplan
