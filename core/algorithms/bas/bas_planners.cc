#include "core/algorithms/bas/bas_planners.h"

#include <memory>
#include <optional>
#include <string>

#include "core/algorithms/bas/beetle_antennae.h"
#include "core/algorithms/bas/seeded_terrain_objective.h"
#include "core/algorithms/bas/terrain_aco.h"
#include "core/algorithms/bas/terrain_objective.h"
#include "core/algorithms/citations.h"
#include "core/operators/waypoint_params.h"
#include "core/seeds/seed_paths.h"

namespace swarmplan {
namespace {

// One member of the family: which mechanisms it switches on.
struct BasVariant {
  std::string id;
  std::string description;
  int iterations = 500;
  int population = 0;     // 0: a single beetle, no population parameter
  bool lfs = false;       // local fast search
  bool sio = false;       // eta parameters of the direction mix
  bool aco_init = false;  // the first path comes from one ACO generation (terrain only)
};

std::vector<ParamSpec> TerrainPenaltyParam() {
  return {ParamSpec::Double("terrain_penalty", 100.0, 0.0, 1e12, "",
                            "fitness added per height unit of depth below ground + clearance, "
                            "summed over samples every quarter cell (terrain only)")
              .Ours()};
}

// The lengths the paper gives in cells (step, rationality step, band widening), in world units
// on a terrain: times its cell size, so a terrain of unit cells runs the paper's numbers. A
// relative step (init=seeded) is a fraction of the coordinates' ranges and stays as it is.
BeetleAntennaeOptions InWorldUnits(BeetleAntennaeOptions options, const PathObjective& objective) {
  const auto* terrain = dynamic_cast<const TerrainObjective*>(&objective);
  if (terrain == nullptr) return options;
  const double cell = terrain->terrain().cell_size();
  if (!options.relative_steps) options.step0 *= cell;
  options.theta0 *= cell;
  options.band_step *= cell;
  return options;
}

std::vector<ParamSpec> AcoParams() {
  return {
      ParamSpec::Int("ants", 20, 1, 10000, "", "ants per generation").PopulationSize(),
      ParamSpec::Double("aco_alpha", 1.0, 0.0, 10.0, "", "pheromone exponent").Ours(),
      ParamSpec::Double("local_keep", 0.5, 0.0, 1.0, "",
                        "local update tau <- local_keep * tau on visited cells"),
      ParamSpec::Double(
          "global_keep", 0.8, 0.0, 1.0, "",
          "global update tau <- global_keep * tau + (1 - global_keep) q s / f_best, s the cell "
          "size"),
      ParamSpec::Double("q", 100.0, 0.0, 1e9, "", "pheromone deposit constant"),
  };
}

TerrainAcoOptions AcoOptionsFrom(const ParamSet& params) {
  TerrainAcoOptions options;
  options.ants = static_cast<int>(params.Int("ants"));
  options.alpha = params.Double("aco_alpha");
  options.local_keep = params.Double("local_keep");
  options.global_keep = params.Double("global_keep");
  options.q = params.Double("q");
  return options;
}

std::vector<ParamSpec> BasParams(const BasVariant& v) {
  std::vector<ParamSpec> specs;
  if (v.aco_init) {
    specs.push_back(ParamSpec::Int("iterations", v.iterations, 1, 1000000, "iterations",
                                   "BAS iterations after the ACO initial path"));
    AppendParams(specs, AcoParams());
  } else {
    specs = WaypointParams(v.iterations, 2);  // 2D use: the paper's two path points
    specs.push_back(ParamSpec::Bool("pso_mix", false,
                                    "2D: mix the direction with a PSO term b <- m b + c1 (x_best "
                                    "- x) rand (eq 19)"));
    specs.push_back(ParamSpec::Double("pso_m", 1.0, 0.0, 100.0, "", "m of eq 19"));
    specs.push_back(ParamSpec::Double("pso_c1", 1.5, 0.0, 100.0, "", "c1 of eq 19"));
  }
  if (v.population > 0) {
    specs.push_back(
        ParamSpec::Int("population", v.population, 1, 10000, "", "beetles").PopulationSize());
  }
  specs.push_back(
      ParamSpec::Enum(
          "init", "seeded", {"seeded", "paper"},
          v.aco_init
              ? "seeded: the beetle moves an offset profile along the terrain-lattice optimum "
                "(in place of the ACO generation, so aco-bas is then bas; see "
                "vertices_per_control), which is also the incumbent: the result is never worse "
                "than it; steps are step_fraction of the map. paper: the paper's ACO initial "
                "path and step0 in cells"
              : "seeded: the beetles start from the exact optimum (on terrain they move an "
                "offset profile along the terrain-lattice optimum, see vertices_per_control, "
                "without the rationality check; on 2D maps the control points of `seeds` seed "
                "paths within their corridors under the fleet objective), which is also the "
                "incumbent: the result is never worse than it; steps are step_fraction of the "
                "map. paper: the paper's one waypoint per column from C_ini (2D: `waypoints` "
                "waypoints over the whole map) and step0 in cells")
          .Ours());
  if (!v.aco_init) {
    specs.push_back(ParamSpec::Int("seeds", 3, 1, kMaxSeedPaths, "",
                                   "init=seeded on 2D maps: seed paths in distinct corridors, "
                                   "the exact optimum first; the beetles are spread over them "
                                   "(terrain: the lattice optimum alone)")
                        .Ours());
  }
  specs.push_back(ParamSpec::Int("vertices_per_control", 8, 1, 100000, "",
                                 "init=seeded on terrain: the beetles move an offset profile along "
                                 "the lattice seed, one control point (dY, dZ) per this many of "
                                 "its vertices, linearly interpolated")
                      .Ours());
  specs.push_back(ParamSpec::Double("step_fraction", 0.003, 0.0, 1.0, "",
                                    "init=seeded, or init=paper with step_units=map: initial "
                                    "step delta0 as a fraction of each coordinate's range "
                                    "(terrain: the map's extent in Y, its height range in Z), so "
                                    "the steps scale with the map")
                      .Ours());
  specs.push_back(ParamSpec::Enum("step_units", "cells", {"cells", "map"},
                                  "init=paper: cells: the initial step is step0 cells (the "
                                  "paper's); map: it is step_fraction of each coordinate's range, "
                                  "as with init=seeded (ignored by init=seeded)")
                      .Ours());
  specs.push_back(ParamSpec::Bool("reject_infeasible", true,
                                  "undo a move whose path is infeasible (below ground + "
                                  "clearance, above the ceiling, or colliding): the beetle stays; "
                                  "false: the paper's moves, which always step")
                      .Ours());
  specs.push_back(ParamSpec::Double("step0", 8.0, 0.0, 1e9, "cells",
                                    "init=paper with step_units=cells: initial step delta0 (on "
                                    "a terrain: times its cell size)"));
  specs.push_back(ParamSpec::Double("step_decay", 0.998, 0.0, 1.0, "", "lambda1: delta decay"));
  specs.push_back(ParamSpec::Double("c", 2.0, 1e-9, 1e9, "", "antennae length d = delta / c"));
  specs.push_back(ParamSpec::Double("theta0", 21.0, 0.0, 1e9, "cells",
                                    "initial rationality step (terrain, eq 13; times its cell "
                                    "size)"));
  specs.push_back(
      ParamSpec::Double("theta_decay", 0.998, 0.0, 1.0, "", "lambda2: theta decay (eq 14)"));
  specs.push_back(ParamSpec::Double("band_step", 0.5, 1e-9, 1e9, "cells",
                                    "c': widening of the initial band C_ini per failed draw (on a "
                                    "terrain: times its cell size)")
                      .Ours());
  AppendParams(specs, TerrainPenaltyParam());
  if (v.lfs) {
    specs.push_back(
        ParamSpec::Int("lfs_steps", 10, 0, 100000, "", "m: local fast search steps").Ours());
    specs.push_back(ParamSpec::Double("lfs_lambda", 0.95, 0.0, 1.0, "", "lambda of eq 9").Ours());
    specs.push_back(ParamSpec::Double("lfs_a", 1.0, 1e-9, 1e9, "", "a of eq 9").Ours());
    specs.push_back(ParamSpec::Double("lfs_b", 1.0, 0.0, 1e9, "", "b of eq 9").Ours());
    specs.push_back(ParamSpec::Double("lfs_gamma", 1.0, 0.0, 1e9, "", "gamma of eq 9").Ours());
  }
  if (v.sio) {
    specs.push_back(
        ParamSpec::Double("eta1", 0.6, 0.0, 1e9, "", "weight of the random direction").Ours());
    specs.push_back(
        ParamSpec::Double("eta2", 0.2, 0.0, 1e9, "", "weight toward the swarm's best").Ours());
    specs.push_back(ParamSpec::Double("eta3", 0.2, 0.0, 1e9, "",
                                      "weight of the previous better-antenna direction")
                        .Ours());
  }
  return specs;
}

// How a BAS planner initialises: the waypoint planners' seeding (init, seeds) and on terrain
// the spacing of the seed's offset profile.
struct BasSeeding : WaypointSeeding {
  int vertices_per_control = 8;
};

BasSeeding PaperSeeding() {
  BasSeeding seeding;
  seeding.seeded = false;
  return seeding;
}

// `seeding.seeded`: on terrain the objective is the offset profile along the lattice optimum
// (SeededTerrainObjective), on 2D maps the seeded waypoint objective.
PathSearchPlanner::ObjectiveFactory BasObjectiveFactory(
    std::optional<WaypointFitnessOptions> waypoints, double terrain_penalty, BasSeeding seeding) {
  return [waypoints, terrain_penalty,
          seeding](const Problem& problem) -> absl::StatusOr<std::unique_ptr<PathObjective>> {
    if (problem.map != nullptr && problem.map->is_3d()) {
      absl::StatusOr<std::unique_ptr<TerrainObjective>> objective =
          TerrainObjective::Create(problem, terrain_penalty);
      if (!objective.ok()) return objective.status();
      if (seeding.seeded) {
        absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 1, StopToken());
        if (!seeds.ok()) return seeds.status();
        if (seeds->empty()) {
          return absl::NotFoundError("init=seeded: no lattice path from start to goal exists");
        }
        return std::unique_ptr<PathObjective>(std::make_unique<SeededTerrainObjective>(
            std::move(*objective), std::move(seeds->front().path), seeding.vertices_per_control));
      }
      return std::unique_ptr<PathObjective>(std::move(*objective));
    }
    if (!waypoints.has_value()) {
      return absl::InvalidArgumentError("this planner needs a terrain map");
    }
    return WaypointObjectiveFactory(*waypoints,
                                    static_cast<const WaypointSeeding&>(seeding))(problem);
  };
}

std::unique_ptr<Planner> MakeBasPlanner(const BasVariant& v, const ParamSet& params) {
  BeetleAntennaeOptions options;
  options.population = static_cast<int>(IntOr(params, "population", 1));
  BasSeeding seeding;
  seeding.seeded = params.Enum("init") == "seeded";
  seeding.seeds = static_cast<int>(IntOr(params, "seeds", 1));
  seeding.vertices_per_control = static_cast<int>(params.Int("vertices_per_control"));
  options.relative_steps = seeding.seeded || params.Enum("step_units") == "map";
  options.step0 = options.relative_steps ? params.Double("step_fraction") : params.Double("step0");
  options.reject_infeasible = params.Bool("reject_infeasible");
  options.step_decay = params.Double("step_decay");
  options.c = params.Double("c");
  options.theta0 = params.Double("theta0");
  options.theta_decay = params.Double("theta_decay");
  options.band_step = params.Double("band_step");
  options.lfs_steps = static_cast<int>(IntOr(params, "lfs_steps", 0));
  options.lfs_lambda = DoubleOr(params, "lfs_lambda", options.lfs_lambda);
  options.lfs_a = DoubleOr(params, "lfs_a", options.lfs_a);
  options.lfs_b = DoubleOr(params, "lfs_b", options.lfs_b);
  options.lfs_gamma = DoubleOr(params, "lfs_gamma", options.lfs_gamma);
  options.eta1 = DoubleOr(params, "eta1", 1.0);
  options.eta2 = DoubleOr(params, "eta2", 0.0);
  options.eta3 = DoubleOr(params, "eta3", 0.0);
  options.pso_mix = BoolOr(params, "pso_mix", false);
  options.pso_m = DoubleOr(params, "pso_m", options.pso_m);
  options.pso_c1 = DoubleOr(params, "pso_c1", options.pso_c1);
  std::optional<WaypointFitnessOptions> waypoints;
  if (!v.aco_init) waypoints = WaypointFitnessFrom(params);
  std::optional<TerrainAcoOptions> aco;
  if (v.aco_init && !seeding.seeded) aco = AcoOptionsFrom(params);
  return std::make_unique<PathSearchPlanner>(
      BasObjectiveFactory(waypoints, params.Double("terrain_penalty"), seeding),
      [options, aco](PathObjective& objective, int t_max, Rng& rng, const StopToken& stop,
                     Observer& observer) -> absl::StatusOr<SearchOutcome> {
        std::optional<Eigen::VectorXd> seed;
        int64_t initial_evaluations = 0;
        if (aco.has_value()) {
          auto* terrain = dynamic_cast<TerrainObjective*>(&objective);
          if (terrain == nullptr) return absl::InvalidArgumentError("needs a terrain map");
          absl::StatusOr<TerrainAco> colony = TerrainAco::Create(*terrain, *aco);
          if (!colony.ok()) return colony.status();
          Evaluation best;
          double mean = 0.0;
          seed = colony->Generation(rng, best, mean, initial_evaluations);
        }
        SearchOutcome out = RunBeetleAntennae(objective, InWorldUnits(options, objective), t_max,
                                              rng, stop, observer, seed);
        out.evaluations += initial_evaluations;
        return out;
      },
      static_cast<int>(params.Int("iterations")));
}

PlannerInfo BasFamilyInfo(const BasVariant& v) {
  PlannerInfo info;
  info.id = v.id;
  info.description = v.description;
  info.seed_paper = citations::kBeetleAntennae3d;
  info.encoding = Encoding::kColumns;
  info.map_kinds = {MapKind::kTerrain};
  if (!v.aco_init) {
    info.map_kinds.push_back(MapKind::kShapeWorld);
    info.map_kinds.push_back(MapKind::kOccupancyGrid);
  }
  info.params = BasParams(v);
  info.factory = [v](const ParamSet& params) { return MakeBasPlanner(v, params); };
  return info;
}

}  // namespace

PlannerInfo TerrainAcoInfo() {
  PlannerInfo info;
  info.id = "aco";
  info.description =
      "Ant colony on a terrain, the baseline of seed 000: ants build one waypoint per column "
      "from the 5 x 5 (Y, Z) neighbourhood of the previous one, weighted by pheromone and "
      "H = S x D x M (validity, short steps toward the goal, low flight); local and global "
      "pheromone updates. Ours: the exact D and M terms, tau_min = 1e-3, height levels one cell "
      "size apart.";
  info.seed_paper = citations::kBeetleAntennae3d;
  info.encoding = Encoding::kColumns;
  info.map_kinds = {MapKind::kTerrain};
  info.params.push_back(
      ParamSpec::Int("iterations", 500, 1, 1000000, "iterations", "generations of the colony"));
  AppendParams(info.params, AcoParams());
  AppendParams(info.params, TerrainPenaltyParam());
  info.factory = [](const ParamSet& params) -> std::unique_ptr<Planner> {
    const TerrainAcoOptions aco = AcoOptionsFrom(params);
    return std::make_unique<PathSearchPlanner>(
        BasObjectiveFactory(std::nullopt, params.Double("terrain_penalty"), PaperSeeding()),
        [aco](PathObjective& objective, int t_max, Rng& rng, const StopToken& stop,
              Observer& observer) -> absl::StatusOr<SearchOutcome> {
          auto* terrain = dynamic_cast<TerrainObjective*>(&objective);
          if (terrain == nullptr) return absl::InvalidArgumentError("aco needs a terrain map");
          absl::StatusOr<TerrainAco> colony = TerrainAco::Create(*terrain, aco);
          if (!colony.ok()) return colony.status();
          return colony->Run(t_max, rng, stop, observer);
        },
        static_cast<int>(params.Int("iterations")));
  };
  return info;
}

namespace {

constexpr char kModel[] =
    " On a terrain (world units; lengths given in cells are times the cell size s): one "
    "waypoint (Y, Z) per column, fitness sum(sqrt(s^2 + dY^2 + dZ^2) + Z) plus a penalty for "
    "flying below ground + clearance (ours), path rationality check (eqs 13-14), first path "
    "drawn from the widening band C_ini (c' = 0.5 cells, ours): init=paper. init=seeded (the "
    "default, ours): the beetles move an offset profile along the terrain-lattice optimum, "
    "steps a fraction of the map, infeasible moves undone, never worse than the seed. On 2D "
    "maps: k = 2 waypoints joined by a cubic spline, fitness L (1 + M xi), optional PSO mix "
    "(eq 19).";

}  // namespace

PlannerInfo BasInfo() {
  return BasFamilyInfo({"bas",
                        std::string("Beetle antennae search: one beetle, random direction b, "
                                    "antennae x +- (delta/c) b, step delta toward the better "
                                    "antenna, delta <- 0.998 delta.") +
                            kModel,
                        500});
}

PlannerInfo LfsBasInfo() {
  return BasFamilyInfo(
      {"lfs-bas",
       std::string("BAS with local fast search: when a step finds a new best, up to m "
                   "antennae steps from the best with their own decaying step "
                   "(eqs 9-11). Ours: m = 10, lambda = 0.95, a = b = gamma = 1.") +
           kModel,
       500, 0, true});
}

PlannerInfo AcoBasInfo() {
  return BasFamilyInfo(
      {"aco-bas",
       "BAS started from the best path of one ACO generation (20 ants) on a terrain; "
       "rationality check and step schedule as bas. Terrain only.",
       500, 0, false, false, true});
}

PlannerInfo SioBasInfo() {
  return BasFamilyInfo(
      {"sio-bas",
       std::string("Searching-information-oriented BAS: a population whose directions "
                   "mix a random unit vector, the unit vector to the swarm's best and "
                   "the previous better-antenna direction, b = normalise(eta1 b1 + eta2 "
                   "b2 + eta3 b3) (eqs 16-18). Ours: eta = (0.6, 0.2, 0.2).") +
           kModel,
       200, 5, false, true});
}

PlannerInfo MultiBasInfo() {
  return BasFamilyInfo(
      {"multi-bas",
       std::string("A population of independent BAS beetles (sio-bas with eta2 = eta3 "
                   "= 0: no information sharing), the paper's Multi-BAS.") +
           kModel,
       200, 5});
}

}  // namespace swarmplan
