#pragma once

#include "core/registry.h"

namespace swarmplan {

// Each planner family registers its planners; RegisterAllPlanners calls every one of them.
void RegisterExactPlanners(Registry& registry);  // core/graph

void RegisterAllPlanners(Registry& registry);

}  // namespace swarmplan
