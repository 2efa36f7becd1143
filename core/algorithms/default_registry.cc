#include "core/algorithms/register.h"
#include "core/registry.h"

namespace swarmplan {

const Registry& DefaultRegistry() {
  static const Registry* const registry = [] {
    auto* r = new Registry();
    RegisterAllPlanners(*r);
    return r;
  }();
  return *registry;
}

}  // namespace swarmplan
