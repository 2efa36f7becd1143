#include "core/algorithms/pso/pso_planner.h"

#include <memory>

#include "core/algorithms/bso/beetle_swarm.h"
#include "core/algorithms/bso/swarm_options.h"
#include "core/algorithms/citations.h"
#include "core/operators/waypoint_params.h"

namespace swarmplan {

PlannerInfo PsoInfo() {
  PlannerInfo info;
  info.id = "pso";
  info.description =
      "Particle swarm optimisation over k waypoints joined by a cubic spline (the baseline of "
      "seeds 000 and 002): linear inertia 0.9 -> 0.4, c1 = c2 = 2, random initialisation, "
      "fitness L (1 + M xi). It is the beetle swarm loop with the antennae term switched off. "
      "Ours: velocity clamp 20% of the span, k = 3 waypoints.";
  info.seed_paper = citations::kPso;
  info.encoding = Encoding::kWaypoints;
  info.map_kinds = {MapKind::kShapeWorld, MapKind::kOccupancyGrid};
  info.params = WaypointSeedingParams();
  AppendParams(info.params, WaypointParams(500, 3));
  info.params.push_back(
      ParamSpec::Int("population", 100, 2, 100000, "", "particles").PopulationSize());
  info.params.push_back(ParamSpec::Double("w_max", 0.9, 0.0, 2.0, "", "initial inertia"));
  info.params.push_back(ParamSpec::Double("w_min", 0.4, 0.0, 2.0, "", "final inertia"));
  info.params.push_back(ParamSpec::Double("c1", 2.0, 0.0, 10.0, "", "personal-best factor"));
  info.params.push_back(ParamSpec::Double("c2", 2.0, 0.0, 10.0, "", "global-best factor"));
  info.params.push_back(ParamSpec::Double("velocity_fraction", 0.2, 0.0, 10.0, "",
                                          "velocity clamp as a fraction of the span")
                            .Ours());
  info.params.push_back(PositionsParam());
  info.params.push_back(BoxInsetParam());
  info.factory = [](const ParamSet& params) -> std::unique_ptr<Planner> {
    const BeetleSwarmOptions options = PsoOptionsFromParams(params);
    return std::make_unique<PathSearchPlanner>(
        WaypointObjectiveFactory(WaypointFitnessFrom(params), WaypointSeedingFrom(params)),
        [options](PathObjective& objective, int t_max, Rng& rng, const StopToken& stop,
                  Observer& observer) -> absl::StatusOr<SearchOutcome> {
          return RunBeetleSwarm(objective, options, t_max, rng, stop, observer);
        },
        static_cast<int>(params.Int("iterations")));
  };
  return info;
}

}  // namespace swarmplan
