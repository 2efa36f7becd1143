#pragma once

#include "absl/status/status.h"
#include "core/registry.h"

namespace swarmplan {

// Registers every planner swarmplan ships, in the order clients list them. The first failure
// (a taken id or an incomplete info: a programming error) is returned and nothing after it is
// registered.
absl::Status RegisterAllPlanners(Registry& registry);

}  // namespace swarmplan
