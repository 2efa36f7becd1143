#include "core/algorithms/bso/bso_planners.h"

#include <memory>
#include <string>

#include "core/algorithms/bso/beetle_swarm.h"
#include "core/algorithms/bso/swarm_options.h"
#include "core/algorithms/citations.h"
#include "core/operators/waypoint_params.h"

namespace swarmplan {
namespace {

std::vector<ParamSpec> SwarmParams(bool aem, const std::string& inertia) {
  std::vector<ParamSpec> specs = WaypointSeedingParams();
  AppendParams(specs, WaypointParams(500, 3));
  specs.push_back(ParamSpec::Int("population", 100, 2, 100000, "", "beetles").PopulationSize());
  specs.push_back(ParamSpec::Enum("inertia", inertia, {"linear", "cosine"},
                                  "inertia schedule: linear (eq 4) or cos(pi/2 sqrt(t/tmax)) "
                                  "(eq 6)"));
  specs.push_back(ParamSpec::Double("w_max", 0.9, 0.0, 2.0, "", "largest inertia weight"));
  specs.push_back(ParamSpec::Double("w_min", 0.4, 0.0, 2.0, "", "smallest inertia weight"));
  specs.push_back(ParamSpec::Double("c1", 1.49, 0.0, 10.0, "", "personal-best factor"));
  specs.push_back(ParamSpec::Double("c2", 1.49, 0.0, 10.0, "", "global-best factor"));
  specs.push_back(ParamSpec::Double("c3", 1.49, 0.0, 10.0, "", "antennae factor"));
  specs.push_back(ParamSpec::Double("step_fraction", 0.05, 0.0, 1.0, "",
                                    "initial antennae step delta as a fraction of the mean span")
                      .Ours());
  specs.push_back(
      ParamSpec::Double("step_decay", 0.99, 0.0, 1.0, "", "delta <- step_decay * delta").Ours());
  specs.push_back(ParamSpec::Double("velocity_fraction", 0.2, 0.0, 10.0, "",
                                    "velocity clamp as a fraction of the span")
                      .Ours());
  specs.push_back(PositionsParam());
  specs.push_back(BoxInsetParam());
  if (aem) {
    specs.push_back(
        ParamSpec::Double("k1", 0.1, -100.0, 100.0, "", "elite mutation G1 = k1 t / tmax (eq 7)")
            .Ours());
    specs.push_back(ParamSpec::Double("k2", 0.1, -100.0, 100.0, "",
                                      "elite mutation G2 = k2 exp(k3 (f_avg - f_gbest)) (eq 8)")
                        .Ours());
    specs.push_back(
        ParamSpec::Double("k3", -1.0, -100.0, 100.0, "", "elite mutation exponent factor (eq 8)")
            .Ours());
  }
  return specs;
}

PlannerInfo SwarmInfo(const std::string& id, const std::string& description, bool aem,
                      const std::string& inertia) {
  PlannerInfo info;
  info.id = id;
  info.description = description;
  info.seed_paper = citations::kAemBso;
  info.encoding = Encoding::kWaypoints;
  info.map_kinds = {MapKind::kShapeWorld, MapKind::kOccupancyGrid};
  info.params = SwarmParams(aem, inertia);
  info.factory = [aem](const ParamSet& params) -> std::unique_ptr<Planner> {
    const BeetleSwarmOptions options = BeetleSwarmOptionsFromParams(aem, params);
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

}  // namespace

PlannerInfo BsoInfo() {
  return SwarmInfo("bso",
                   "Beetle swarm optimisation (eqs 1-4): PSO velocities plus an antennae term "
                   "-delta b sign(f_r - f_l), random initialisation, linear inertia. Path: k "
                   "waypoints joined by a cubic spline, fitness L (1 + M xi). Ours: delta0 = 5% of "
                   "the span decaying by 0.99, velocity clamp 20% of the span, k = 3 waypoints.",
                   false, "linear");
}

PlannerInfo AemBsoInfo() {
  return SwarmInfo("aem-bso",
                   "Adaptive elite mutation BSO: BSO with good point set initialisation (eq 5), "
                   "nonlinear inertia w_min + (w_max - w_min) cos(pi/2 sqrt(t/tmax)) (eq 6) and "
                   "elite mutation gbest (1 +- (G1 + G2 + mu)) kept when better (eqs 7-9). Ours: "
                   "k1 = k2 = 0.1, k3 = -1 (the paper gives none), plus the BSO choices of `bso`.",
                   true, "cosine");
}

PlannerInfo AemBsoLinearInfo() {
  return SwarmInfo("aem-bso-linear",
                   "AEM-BSO with the linear inertia of eq 4 (the paper's AEM-BSO2); otherwise "
                   "identical to aem-bso.",
                   true, "linear");
}

}  // namespace swarmplan
