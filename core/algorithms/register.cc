#include "core/algorithms/register.h"

namespace swarmplan {

void RegisterAllPlanners(Registry& registry) {
  RegisterExactPlanners(registry);
  RegisterBeetlePlanners(registry);
  RegisterGridPlanners(registry);
}

}  // namespace swarmplan
