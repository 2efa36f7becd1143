#include "core/algorithms/register.h"

#include <vector>

#include "core/algorithms/afsa/fish_swarm.h"
#include "core/algorithms/bas/bas_planners.h"
#include "core/algorithms/baselines/ba_planner.h"
#include "core/algorithms/baselines/grid_baselines.h"
#include "core/algorithms/bfo/as_bfo.h"
#include "core/algorithms/bpso/binary_pso.h"
#include "core/algorithms/bso/bso_planners.h"
#include "core/algorithms/exact/exact_any_angle.h"
#include "core/algorithms/exact/exact_planners.h"
#include "core/algorithms/exact/terrain_lattice_planner.h"
#include "core/algorithms/pso/pso_planner.h"

namespace swarmplan {

// The catalogue: the one place that lists every planner.
absl::Status RegisterAllPlanners(Registry& registry) {
  std::vector<PlannerInfo> infos = {
      // Exact planners: the yardsticks.
      ExactAnyAngleInfo(), AStarInfo(), DijkstraInfo(), ThetaStarInfo(), VisibilityGraphInfo(),
      TerrainLatticeInfo(),
      // Beetle swarms and their baselines over spline waypoints.
      BsoInfo(), AemBsoInfo(), AemBsoLinearInfo(), PsoInfo(), BatInfo(),
      // The beetle antennae family (terrain and 2D) and its ACO baseline.
      BasInfo(), LfsBasInfo(), AcoBasInfo(), SioBasInfo(), MultiBasInfo(), TerrainAcoInfo(),
      // Grid-node and vertex planners and the grid baselines.
      AsBfoInfo(), AfsaInfo(), DafsaInfo(), IdafsaInfo(), BinaryPsoInfo(), GridGaInfo(),
      GridAcoInfo(), GridApfInfo()};
  for (PlannerInfo& info : infos) {
    if (absl::Status s = registry.Register(std::move(info)); !s.ok()) return s;
  }
  return absl::OkStatus();
}

}  // namespace swarmplan
