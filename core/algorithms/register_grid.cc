#include "core/algorithms/afsa/fish_swarm.h"
#include "core/algorithms/baselines/grid_baselines.h"
#include "core/algorithms/bfo/as_bfo.h"
#include "core/algorithms/bpso/binary_pso.h"
#include "core/algorithms/register.h"

namespace swarmplan {

// The grid and vertex planners of issue 5: AS-BFO, the fish swarms, binary PSO and the grid
// baselines.
void RegisterGridPlanners(Registry& registry) {
  for (PlannerInfo info : {AsBfoInfo(), AfsaInfo(), DafsaInfo(), IdafsaInfo(), BinaryPsoInfo(),
                           GridGaInfo(), GridAcoInfo(), GridApfInfo()}) {
    // The infos are ours and complete; a failure here is a programming error caught by tests.
    (void)registry.Register(std::move(info));
  }
}

}  // namespace swarmplan
