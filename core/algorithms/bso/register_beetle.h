#pragma once

#include "core/registry.h"

namespace swarmplan {

// The families RegisterBeetlePlanners (core/algorithms/register.h) is made of.
void RegisterBsoPlanners(Registry& registry);  // bso, aem-bso, aem-bso-linear
void RegisterPsoPlanner(Registry& registry);   // pso
void RegisterBatPlanner(Registry& registry);   // ba
void RegisterBasPlanners(Registry& registry);  // bas, lfs-bas, aco-bas, sio-bas, multi-bas, aco

// Registers our own planner; aborts on failure, which only a programming error can cause.
void MustRegisterPlanner(Registry& registry, PlannerInfo info);

}  // namespace swarmplan
