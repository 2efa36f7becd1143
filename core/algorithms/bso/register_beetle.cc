#include "core/algorithms/bso/register_beetle.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/algorithms/register.h"

namespace swarmplan {

void MustRegisterPlanner(Registry& registry, PlannerInfo info) {
  const std::string id = info.id;
  const absl::Status status = registry.Register(std::move(info));
  if (!status.ok()) {
    std::fprintf(stderr, "registering planner '%s' failed: %s\n", id.c_str(),
                 std::string(status.message()).c_str());
    std::abort();
  }
}

void RegisterBeetlePlanners(Registry& registry) {
  RegisterBsoPlanners(registry);
  RegisterPsoPlanner(registry);
  RegisterBatPlanner(registry);
  RegisterBasPlanners(registry);
}

}  // namespace swarmplan
