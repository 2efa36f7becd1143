#include "core/algorithms/exact/terrain_lattice_planner.h"

#include <memory>
#include <utility>

#include "absl/time/clock.h"
#include "core/algorithms/citations.h"
#include "core/algorithms/exact/exact_search_result.h"
#include "core/algorithms/exact/terrain_lattice.h"

namespace swarmplan {
namespace {

class TerrainLatticePlanner final : public Planner {
 public:
  explicit TerrainLatticePlanner(TerrainLatticeOptions options) : options_(options) {}

  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override {
    const Terrain* terrain = problem.map != nullptr ? problem.map->terrain() : nullptr;
    if (terrain == nullptr) {
      return absl::FailedPreconditionError(
          "algorithm 'terrain-lattice' plans on terrain maps only");
    }
    if (StopReason reason = stop.Check(0); reason != StopReason::kNone) {
      return StoppedExactSearch(reason);
    }
    const absl::Time started = absl::Now();
    TerrainLatticeOptions options = options_;
    options.stop = &stop;
    absl::StatusOr<TerrainLatticeResult> lattice =
        TerrainLatticeOptimum(*terrain, problem.start, problem.goal, problem.clearance, options);
    if (!lattice.ok()) return lattice.status();
    if (lattice->stopped) return StoppedExactSearch(stop.Check(0));
    return FinishExactSearch(std::move(lattice->path), lattice->cost, lattice->expanded, started,
                             observer);
  }

 private:
  TerrainLatticeOptions options_;
};

}  // namespace

PlannerInfo TerrainLatticeInfo() {
  PlannerInfo info;
  info.id = "terrain-lattice";
  info.description =
      "Exact search on the voxel lattice of a terrain: nodes at the cell centres times height "
      "levels (from the lowest ground + clearance up to the ceiling, vertical_step apart), the "
      "26-neighbourhood, edges kept when the segment keeps the clearance under the ceiling by "
      "the exact terrain collision checker, start and goal joined to the nodes within one step "
      "of them. A* minimises the terrain planners' own objective in world units (each segment: "
      "its length plus the height of its end per cell of x-advance; the BAS fitness of seed 000 "
      "on one-waypoint-per-column paths). The result is a lattice optimum: exact on the "
      "lattice, an upper bound on the optimum over all continuous paths. One iteration.";
  info.seed_paper = citations::kAStar;  // A* on the lattice, the objective of the BAS paper
  info.encoding = Encoding::kExact;
  info.map_kinds = {MapKind::kTerrain};
  info.params = {
      ParamSpec::Double("vertical_step", 0.0, 0.0, 1e12, "height units",
                        "height between lattice levels; 0: the cell size, raised so that there "
                        "are at most max_levels levels")
          .Ours(),
      ParamSpec::Int("max_levels", 64, 2, 4096, "", "most height levels when vertical_step is 0")
          .Ours(),
  };
  info.factory = [](const ParamSet& params) -> std::unique_ptr<Planner> {
    TerrainLatticeOptions options;
    options.vertical_step = params.Double("vertical_step");
    options.max_levels = static_cast<int>(params.Int("max_levels"));
    return std::make_unique<TerrainLatticePlanner>(options);
  };
  return info;
}

}  // namespace swarmplan
