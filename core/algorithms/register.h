#pragma once

#include "core/registry.h"

namespace swarmplan {

// Each planner family registers its planners; RegisterAllPlanners calls every one of them.
void RegisterExactPlanners(Registry& registry);   // core/graph
void RegisterBeetlePlanners(Registry& registry);  // core/algorithms/{bas,bso,pso,baselines}
void RegisterGridPlanners(Registry& registry);    // core/algorithms/{bfo,afsa,bpso,baselines}

void RegisterAllPlanners(Registry& registry);

}  // namespace swarmplan
