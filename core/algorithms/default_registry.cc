#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/algorithms/register.h"
#include "core/registry.h"

namespace swarmplan {

const Registry& DefaultRegistry() {
  static const Registry* const registry = [] {
    auto* r = new Registry();
    // Our own catalogue can only fail through a programming error, which the registry tests
    // catch; a process must not run with half a catalogue.
    if (absl::Status s = RegisterAllPlanners(*r); !s.ok()) {
      std::fprintf(stderr, "swarmplan: the planner catalogue is broken: %s\n",
                   std::string(s.message()).c_str());
      std::abort();
    }
    return r;
  }();
  return *registry;
}

}  // namespace swarmplan
