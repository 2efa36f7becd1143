#include "core/algorithms/bso/swarm_options.h"

#include "absl/strings/str_cat.h"

namespace swarmplan {
namespace {

PositionBound PositionsFrom(const ParamSet& params) {
  return params.Enum("positions") == "far" ? PositionBound::kFar : PositionBound::kBox;
}

}  // namespace

ParamSpec PositionsParam() {
  return ParamSpec::Enum("positions", "box", {"box", "far"},
                         "box: every move is clamped to the search box; far: positions may "
                         "leave it, up to 10 times its span on each side (the box then bounds "
                         "the initial population and the velocities only)")
      .Ours();
}

BeetleSwarmOptions BeetleSwarmOptionsFromParams(bool aem, const ParamSet& params) {
  BeetleSwarmOptions options;
  options.population = static_cast<int>(params.Int("population"));
  options.good_point_init = aem;
  options.inertia = *ParseInertiaSchedule(params.Enum("inertia"));
  options.w_max = params.Double("w_max");
  options.w_min = params.Double("w_min");
  options.c1 = params.Double("c1");
  options.c2 = params.Double("c2");
  options.c3 = params.Double("c3");
  options.step_fraction = params.Double("step_fraction");
  options.step_decay = params.Double("step_decay");
  options.velocity_fraction = params.Double("velocity_fraction");
  options.positions = PositionsFrom(params);
  options.elite_mutation = aem;
  if (aem) options.mutation = {params.Double("k1"), params.Double("k2"), params.Double("k3")};
  return options;
}

BeetleSwarmOptions PsoOptionsFromParams(const ParamSet& params) {
  BeetleSwarmOptions options;
  options.population = static_cast<int>(params.Int("population"));
  options.antennae = false;
  options.inertia = InertiaSchedule::kLinear;
  options.w_max = params.Double("w_max");
  options.w_min = params.Double("w_min");
  options.c1 = params.Double("c1");
  options.c2 = params.Double("c2");
  options.velocity_fraction = params.Double("velocity_fraction");
  options.positions = PositionsFrom(params);
  return options;
}

BatOptions BatOptionsFromParams(const ParamSet& params) {
  BatOptions options;
  options.population = static_cast<int>(params.Int("population"));
  options.f_min = params.Double("f_min");
  options.f_max = params.Double("f_max");
  options.loudness0 = params.Double("loudness0");
  options.pulse_rate0 = params.Double("pulse_rate0");
  options.alpha = params.Double("alpha");
  options.gamma = params.Double("gamma");
  options.walk_fraction = params.Double("walk_fraction");
  options.velocity_fraction = params.Double("velocity_fraction");
  options.pulse_schedule = *ParsePulseSchedule(params.Enum("pulse_schedule"));
  options.positions = PositionsFrom(params);
  return options;
}

namespace {

SwarmOptimiser BeetleSwarm(BeetleSwarmOptions options) {
  return [options](Objective& objective, int t_max, Rng& rng, const StopToken& stop,
                   Observer& observer) {
    return RunBeetleSwarm(objective, options, t_max, rng, stop, observer);
  };
}

}  // namespace

absl::StatusOr<SwarmOptimiser> SwarmOptimiserFor(const std::string& planner_id,
                                                 const ParamSet& params) {
  if (planner_id == "bso") return BeetleSwarm(BeetleSwarmOptionsFromParams(false, params));
  if (planner_id == "aem-bso" || planner_id == "aem-bso-linear") {
    return BeetleSwarm(BeetleSwarmOptionsFromParams(true, params));
  }
  if (planner_id == "pso") return BeetleSwarm(PsoOptionsFromParams(params));
  if (planner_id == "ba") {
    return SwarmOptimiser([options = BatOptionsFromParams(params)](Objective& objective, int t_max,
                                                                   Rng& rng, const StopToken& stop,
                                                                   Observer& observer) {
      return RunBatAlgorithm(objective, options, t_max, rng, stop, observer);
    });
  }
  return absl::NotFoundError(absl::StrCat("no swarm optimiser for planner '", planner_id,
                                          "'; known: bso, aem-bso, aem-bso-linear, pso, ba"));
}

}  // namespace swarmplan
