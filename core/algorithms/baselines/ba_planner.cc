#include "core/algorithms/baselines/ba_planner.h"

#include <memory>

#include "core/algorithms/baselines/ba.h"
#include "core/algorithms/bso/swarm_options.h"
#include "core/algorithms/citations.h"
#include "core/operators/waypoint_params.h"

namespace swarmplan {

PlannerInfo BatInfo() {
  PlannerInfo info;
  info.id = "ba";
  info.description =
      "Bat algorithm (Yang 2010) over k waypoints joined by a cubic spline, fitness "
      "L (1 + M xi), the BA baseline of seed 002: frequency-tuned velocities toward the best "
      "bat, local walks around it at rate 1 - r, acceptance by loudness; alpha = gamma = 0.9. "
      "Ours: f in [0, 2], A0 = 1, r0 = 0.5, local walk scaled by 1% of the span, k = 3.";
  info.seed_paper = citations::kBat;
  info.encoding = Encoding::kWaypoints;
  info.map_kinds = {MapKind::kShapeWorld, MapKind::kOccupancyGrid};
  info.params = WaypointSeedingParams();
  AppendParams(info.params, WaypointParams(500, 3));
  info.params.push_back(ParamSpec::Int("population", 100, 2, 100000, "", "bats").PopulationSize());
  info.params.push_back(ParamSpec::Double("f_min", 0.0, 0.0, 100.0, "", "lowest frequency").Ours());
  info.params.push_back(
      ParamSpec::Double("f_max", 2.0, 0.0, 100.0, "", "highest frequency").Ours());
  info.params.push_back(
      ParamSpec::Double("loudness0", 1.0, 0.0, 10.0, "", "initial loudness").Ours());
  info.params.push_back(
      ParamSpec::Double("pulse_rate0", 0.5, 0.0, 1.0, "", "final pulse rate r0").Ours());
  info.params.push_back(ParamSpec::Double("alpha", 0.9, 0.0, 1.0, "", "loudness decay"));
  info.params.push_back(ParamSpec::Double("gamma", 0.9, 0.0, 100.0, "", "pulse rate growth"));
  info.params.push_back(
      ParamSpec::Enum("pulse_schedule", "on-accept", {"on-accept", "per-iteration"},
                      "when r_i = r0 (1 - exp(-gamma t)): on-accept, when bat i accepts a "
                      "candidate (from r_i = r0); per-iteration, for every bat at every "
                      "iteration (from r_i = 0)")
          .Ours());
  info.params.push_back(ParamSpec::Double("velocity_fraction", 0.0, 0.0, 10.0, "",
                                          "velocity bound as a fraction of each coordinate's "
                                          "span; 0: no bound (Yang's BA)")
                            .Ours());
  info.params.push_back(ParamSpec::Double("walk_fraction", 0.01, 0.0, 1.0, "",
                                          "local walk scale as a fraction of the span")
                            .Ours());
  info.params.push_back(PositionsParam());
  info.params.push_back(BoxInsetParam());
  info.factory = [](const ParamSet& params) -> std::unique_ptr<Planner> {
    const BatOptions options = BatOptionsFromParams(params);
    return std::make_unique<PathSearchPlanner>(
        WaypointObjectiveFactory(WaypointFitnessFrom(params), WaypointSeedingFrom(params)),
        [options](PathObjective& objective, int t_max, Rng& rng, const StopToken& stop,
                  Observer& observer) -> absl::StatusOr<SearchOutcome> {
          return RunBatAlgorithm(objective, options, t_max, rng, stop, observer);
        },
        static_cast<int>(params.Int("iterations")));
  };
  return info;
}

}  // namespace swarmplan
