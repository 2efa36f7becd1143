#include "core/operators/waypoint_params.h"

#include <algorithm>

#include "core/operators/seeded_waypoint_objective.h"
#include "core/seeds/seed_paths.h"

namespace swarmplan {

std::vector<ParamSpec> WaypointParams(int default_iterations, int default_waypoints) {
  std::vector<ParamSpec> specs;
  specs.push_back(ParamSpec::Int("iterations", default_iterations, 1, 1000000, "iterations",
                                 "generations of the swarm (the problem's iteration cap lowers "
                                 "it; the inertia and step schedules plan with the lower one)"));
  specs.push_back(ParamSpec::Int("waypoints", default_waypoints, 1, 64, "",
                                 "free waypoints between start and goal (decision vector "
                                 "[x1..xk, y1..yk])")
                      .Ours());
  specs.push_back(ParamSpec::Enum("interpolation", "spline", InterpolationNames(),
                                  "how waypoints are joined: not-a-knot cubic spline, straight "
                                  "segments, or nearest-neighbour staircase (AEM-BSO Table 2)"));
  specs.push_back(
      ParamSpec::Int("samples", 100, 4, 100000, "", "points sampled along the spline").Ours());
  specs.push_back(
      ParamSpec::Double("penalty", 100.0, 0.0, 1e12, "", "M in the fitness L (1 + M xi)"));
  specs.push_back(ParamSpec::Double("d_safe", 1.5, 0.0, 1e9, "map units",
                                    "safety distance: xi counts the obstacles the path comes "
                                    "closer to than max(d_safe, clearance)"));
  return specs;
}

std::vector<ParamSpec> SeedingParams(const std::string& seeded_meaning,
                                     const std::string& paper_meaning) {
  std::vector<ParamSpec> specs;
  specs.push_back(ParamSpec::Enum("init", "seeded", {"seeded", "paper"},
                                  "seeded: " + seeded_meaning + ". paper: " + paper_meaning)
                      .Ours());
  specs.push_back(ParamSpec::Int("seeds", 3, 1, kMaxSeedPaths, "",
                                 "init=seeded: seed paths in distinct corridors, the exact "
                                 "optimum first; the population is spread over them")
                      .Ours());
  return specs;
}

std::vector<ParamSpec> WaypointSeedingParams() {
  return SeedingParams(
      "the swarm moves the control points of exact seed paths (one per seed vertex and segment, "
      "at most 1024) within their corridors and minimises the fleet objective (length, preferred "
      "clearance, turning radius); it never returns a path worse than its best seed",
      "the paper's initialisation over the whole map, `waypoints` waypoints, fitness "
      "L (1 + M xi)");
}

ParamSpec BoxInsetParam() {
  return ParamSpec::Double("box_inset", 0.0, 0.0, 1e9, "map units",
                           "init=paper: the search box is the map's rectangle shrunk by this on "
                           "each side (a world larger than the region the paper searches)")
      .Ours();
}

WaypointFitnessOptions WaypointFitnessFrom(const ParamSet& params) {
  WaypointFitnessOptions options;
  options.waypoints = static_cast<int>(params.Int("waypoints"));
  options.interpolation = *ParseInterpolation(params.Enum("interpolation"));
  options.samples = static_cast<int>(params.Int("samples"));
  options.penalty = params.Double("penalty");
  options.d_safe = params.Double("d_safe");
  return options;
}

WaypointSeeding WaypointSeedingFrom(const ParamSet& params) {
  WaypointSeeding seeding;
  seeding.box_inset = DoubleOr(params, "box_inset", 0.0);
  if (!params.values().count("init")) {
    seeding.seeded = false;
    return seeding;
  }
  seeding.seeded = params.Enum("init") == "seeded";
  seeding.seeds = static_cast<int>(params.Int("seeds"));
  return seeding;
}

PathSearchPlanner::ObjectiveFactory WaypointObjectiveFactory(const WaypointFitnessOptions& options,
                                                             const WaypointSeeding& seeding) {
  return
      [options, seeding](const Problem& problem) -> absl::StatusOr<std::unique_ptr<PathObjective>> {
        if (seeding.seeded) {
          absl::StatusOr<std::vector<SeedPath>> seeds =
              FindSeedPaths(problem, std::max(seeding.seeds, problem.alternatives), StopToken());
          if (!seeds.ok()) return seeds.status();
          if (seeds->empty()) {
            return absl::NotFoundError("init=seeded: no path from start to goal exists");
          }
          WaypointFitnessOptions fleet = options;
          fleet.fleet = problem.fleet;
          absl::StatusOr<std::unique_ptr<SeededWaypointObjective>> objective =
              SeededWaypointObjective::Create(problem, fleet, *seeds, kMaxSeededControlPoints);
          if (!objective.ok()) return objective.status();
          return std::unique_ptr<PathObjective>(std::move(*objective));
        }
        absl::StatusOr<std::unique_ptr<WaypointObjective>> objective =
            WaypointObjective::Create(problem, options, seeding.box_inset);
        if (!objective.ok()) return objective.status();
        return std::unique_ptr<PathObjective>(std::move(*objective));
      };
}

double DoubleOr(const ParamSet& params, const std::string& name, double fallback) {
  return params.values().count(name) ? params.Double(name) : fallback;
}
int64_t IntOr(const ParamSet& params, const std::string& name, int64_t fallback) {
  return params.values().count(name) ? params.Int(name) : fallback;
}
bool BoolOr(const ParamSet& params, const std::string& name, bool fallback) {
  return params.values().count(name) ? params.Bool(name) : fallback;
}

void AppendParams(std::vector<ParamSpec>& specs, const std::vector<ParamSpec>& more) {
  specs.insert(specs.end(), more.begin(), more.end());
}

}  // namespace swarmplan
