// The waypoint planners' fitness: the reference path (spline solve per evaluation, exact
// obstacle count) against the FitnessEngine (cached interpolation basis, screened count,
// whole populations), for the papers' L (1 + M xi) and the fleet objective; the end-to-end
// effect on aem-bso; and a streaming read for this machine's memory bandwidth.
//
// BM_Fitness args: map (0 = grid 100 x 100, the 30-circle world rasterised at 1; 1 = world
// with 10 circles; 2 = with 30 circles; 3 = polygons/parking1.geojson; 4 = Moving AI
// Berlin_0_256), k waypoints, samples, impl (0 = reference, 1 = engine one vector per call,
// as the planners call it, 2 = engine on populations of 64, 3 = fleet objective one per call,
// 4 = fleet objective on populations of 64). Items per second = evaluations per CPU second.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "bench/micro/fixtures.h"
#include "core/algorithms/bso/beetle_swarm.h"
#include "core/algorithms/bso/swarm_options.h"
#include "core/fitness/reference_objective.h"
#include "core/geometry/rasterize.h"
#include "core/map/generate.h"
#include "core/map/io/map_io.h"
#include "core/operators/path_search_planner.h"
#include "core/operators/seeded_waypoint_objective.h"
#include "core/operators/waypoint_objective.h"
#include "core/operators/waypoint_params.h"
#include "core/path_metrics.h"
#include "core/random.h"
#include "core/registry.h"
#include "core/seeds/seed_paths.h"

namespace swarmplan::bench {
namespace {

constexpr int kVectors = 1024;
constexpr int kPopulation = 64;

std::string SharedBenchmarks() { return std::string(SWARMPLAN_SHARED_DIR) + "/benchmarks"; }

// The map and the start-goal pair of each map index; null map when its file is missing.
struct FitnessCase {
  MapPtr map;
  Point3 start, goal;
  std::string name;
};

const FitnessCase& Case(int which) {
  static const std::vector<FitnessCase>* const cases = [] {
    const Bounds2 bounds{Point2(0, 0), Point2(100, 100)};
    const std::vector<Point2> keep = {Point2(10, 10), Point2(90, 90)};
    const ShapeWorld ten = ValueOrDie(RandomShapeWorld(bounds, 10, 5, 10, 1, keep, 3));
    const ShapeWorld thirty = ValueOrDie(RandomShapeWorld(bounds, 30, 3, 7, 1, keep, 3));
    auto* out = new std::vector<FitnessCase>();
    out->push_back({std::make_shared<const Map>(ValueOrDie(RasterizeShapeWorld(thirty, 1.0))),
                    {10.5, 10.5, 0},
                    {89.5, 89.5, 0},
                    "grid 100x100"});
    out->push_back({std::make_shared<const Map>(ten), {10, 10, 0}, {90, 90, 0}, "10 circles"});
    out->push_back({std::make_shared<const Map>(thirty), {10, 10, 0}, {90, 90, 0}, "30 circles"});
    for (const std::string file : {"/polygons/parking1.geojson", "/movingai/Berlin_0_256.map"}) {
      absl::StatusOr<Map> map = LoadMapFile(SharedBenchmarks() + file);
      FitnessCase c;
      c.name = file.substr(file.rfind('/') + 1);
      if (map.ok()) {
        c.map = std::make_shared<const Map>(*std::move(map));
        const ObstacleProximity proximity = ValueOrDie(ObstacleProximity::Create(*c.map, 1.5));
        const Point2 lo = proximity.lower(), hi = proximity.upper();
        const Point2 a = lo + 0.1 * (hi - lo), b = lo + 0.9 * (hi - lo);
        c.start = Point3(a.x(), a.y(), 0);
        c.goal = Point3(b.x(), b.y(), 0);
      }
      out->push_back(c);
    }
    return out;
  }();
  return cases->at(which);
}

Problem CaseProblem(const FitnessCase& c, double clearance) {
  Problem problem;
  problem.map = c.map;
  problem.start = c.start;
  problem.goal = c.goal;
  problem.clearance = clearance;
  return problem;
}

// The fleet setting of the real-maps report: hard clearance 0.5, preferred 1.5, radius 2.
FleetObjective FleetSetting() {
  return FleetObjective{.preferred_clearance = 1.5, .turning_radius = 2.0};
}

void BM_Fitness(benchmark::State& state) {
  const FitnessCase& c = Case(static_cast<int>(state.range(0)));
  if (c.map == nullptr) {
    state.SkipWithError("shared benchmark map not found");
    return;
  }
  const int impl = static_cast<int>(state.range(3));
  WaypointFitnessOptions options;
  options.waypoints = static_cast<int>(state.range(1));
  options.samples = static_cast<int>(state.range(2));
  if (impl >= 3) options.fleet = FleetSetting();
  const Problem problem = CaseProblem(c, impl >= 3 ? 0.5 : 0.0);
  auto engine = ValueOrDie(WaypointObjective::Create(problem, options));
  std::unique_ptr<PathObjective> objective = std::move(engine);
  if (impl == 0) objective = ValueOrDie(ReferenceWaypointObjective::Create(problem, options));
  Rng rng(7);
  Eigen::MatrixXd xs(objective->dim(), kVectors);
  Eigen::VectorXd x;
  for (int j = 0; j < kVectors; ++j) {
    objective->SampleAroundStraightPath(30.0, rng, x);
    xs.col(j) = x;
  }
  std::vector<Eigen::VectorXd> columns(kVectors);
  for (int j = 0; j < kVectors; ++j) columns[j] = xs.col(j);
  std::vector<Evaluation> out(kPopulation);
  const bool population = impl == 2 || impl == 4;
  int64_t evaluations = 0, feasible = 0;
  int j = 0;
  for (auto _ : state) {
    if (population) {
      objective->EvaluateColumns(xs.middleCols(j, kPopulation), out.data());
      for (const Evaluation& e : out) feasible += e.feasible ? 1 : 0;
      evaluations += kPopulation;
      j = (j + kPopulation) % kVectors;
    } else {
      const Evaluation e = objective->Evaluate(columns[j]);
      feasible += e.feasible ? 1 : 0;
      ++evaluations;
      j = (j + 1) % kVectors;
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(evaluations);
  state.counters["feasible"] =
      benchmark::Counter(static_cast<double>(feasible) / std::max<int64_t>(1, evaluations));
  static const char* const kImpl[] = {"reference", "engine", "engine x64", "fleet", "fleet x64"};
  state.SetLabel(c.name + ", " + kImpl[impl]);
}

void FitnessArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"map", "k", "samples", "impl"});
  for (int map = 0; map < 5; ++map) {
    for (int k : {2, 3, 5, 8}) {
      for (int samples : {50, 100}) {
        for (int impl = 0; impl < 5; ++impl) b->Args({map, k, samples, impl});
      }
    }
  }
}
BENCHMARK(BM_Fitness)->Apply(FitnessArgs);

// The seeded objective of the fleet setting on Berlin_0_256's longest scenario, the decision
// space a seeded swarm searches (3 seeds, up to 1024 control points, a point every half cell):
// vectors drawn uniformly in the box with the offsets scaled by 0.05, 0.2 and 1 in turn, like
// a population from its start to its end. Arg: 1 = the fleet objective, 0 = the papers'
// penalty. Items per second = evaluations per CPU second; `points` = points per path.
void BM_SeededFitness(benchmark::State& state) {
  const FitnessCase& c = Case(4);
  absl::StatusOr<std::vector<Scenario>> scenarios =
      LoadScenarioFile(SharedBenchmarks() + "/movingai/Berlin_0_256.map.scen");
  if (c.map == nullptr || !scenarios.ok() || scenarios->empty()) {
    state.SkipWithError("shared benchmark map not found");
    return;
  }
  const bool fleet = state.range(0) == 1;
  const Scenario& s = scenarios->back();
  Problem problem = CaseProblem(c, fleet ? 0.5 : 0.0);
  const Point2 start = c.map->grid()->CellCenter(s.start);
  const Point2 goal = c.map->grid()->CellCenter(s.goal);
  problem.start = Point3(start.x(), start.y(), 0);
  problem.goal = Point3(goal.x(), goal.y(), 0);
  WaypointFitnessOptions options;
  if (fleet) options.fleet = FleetSetting();
  const std::vector<SeedPath> seeds = ValueOrDie(FindSeedPaths(problem, 3, StopToken()));
  auto objective =
      ValueOrDie(SeededWaypointObjective::Create(problem, options, seeds, kMaxSeededControlPoints));
  Rng rng(7);
  std::vector<Eigen::VectorXd> columns(kVectors);
  for (int j = 0; j < kVectors; ++j) {
    const double scale = j % 3 == 0 ? 0.05 : j % 3 == 1 ? 0.2 : 1.0;
    Eigen::VectorXd& x = columns[j];
    x.resize(objective->dim());
    x[0] = rng.Uniform(0.0, objective->upper()[0]);
    for (int d = 1; d < x.size(); ++d) x[d] = scale * rng.Uniform(-1.0, 1.0);
  }
  int64_t evaluations = 0, feasible = 0;
  int j = 0;
  for (auto _ : state) {
    feasible += objective->Evaluate(columns[j]).feasible ? 1 : 0;
    ++evaluations;
    j = (j + 1) % kVectors;
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(evaluations);
  state.counters["feasible"] =
      benchmark::Counter(static_cast<double>(feasible) / std::max<int64_t>(1, evaluations));
  state.counters["points"] = static_cast<double>(objective->Decode(columns[0]).size());
  state.counters["control_points"] = objective->control_points();
  state.SetLabel(fleet ? "seeded, fleet" : "seeded, papers' penalty");
}
BENCHMARK(BM_SeededFitness)->Arg(1)->Arg(0);

// aem-bso with its defaults on Berlin_0_256, a long scenario of the last bucket: evaluations per
// CPU second of the whole run (search, bookkeeping, decoding and the final check). Arg: 0 =
// the papers' initialisation with the reference objective, 1 = as registered (init=seeded: up
// to 1024 control points, a point every half cell), 2 = init=paper through the engine (3
// waypoints, 100 samples).
void BM_AemBsoEndToEnd(benchmark::State& state) {
  const FitnessCase& c = Case(4);
  absl::StatusOr<std::vector<Scenario>> scenarios =
      LoadScenarioFile(SharedBenchmarks() + "/movingai/Berlin_0_256.map.scen");
  if (c.map == nullptr || !scenarios.ok() || scenarios->empty()) {
    state.SkipWithError("shared benchmark map not found");
    return;
  }
  const Scenario& s = scenarios->back();
  Problem problem = CaseProblem(c, 0.0);
  const Point2 start = c.map->grid()->CellCenter(s.start);
  const Point2 goal = c.map->grid()->CellCenter(s.goal);
  problem.start = Point3(start.x(), start.y(), 0);
  problem.goal = Point3(goal.x(), goal.y(), 0);
  const PlannerInfo* info = DefaultRegistry().Find("aem-bso");
  const ParamSet params = ValueOrDie(ParamSet::Resolve(info->params, {}));
  std::unique_ptr<Planner> planner;
  if (state.range(0) == 0) {
    const BeetleSwarmOptions options = BeetleSwarmOptionsFromParams(true, params);
    const WaypointFitnessOptions fitness = WaypointFitnessFrom(params);
    planner = std::make_unique<PathSearchPlanner>(
        [fitness](const Problem& p) -> absl::StatusOr<std::unique_ptr<PathObjective>> {
          auto objective = ReferenceWaypointObjective::Create(p, fitness);
          if (!objective.ok()) return objective.status();
          return std::unique_ptr<PathObjective>(std::move(*objective));
        },
        [options](PathObjective& objective, int t_max, Rng& rng, const StopToken& stop,
                  Observer& observer) -> absl::StatusOr<SearchOutcome> {
          return RunBeetleSwarm(objective, options, t_max, rng, stop, observer);
        },
        static_cast<int>(params.Int("iterations")));
  } else if (state.range(0) == 1) {
    planner = ValueOrDie(DefaultRegistry().Create("aem-bso", {}));
  } else {
    planner = ValueOrDie(DefaultRegistry().Create("aem-bso", {{"init", std::string("paper")}}));
  }
  int64_t evaluations = 0;
  double length = 0.0;
  for (auto _ : state) {
    NullObserver observer;
    const SearchResult result = ValueOrDie(planner->Solve(problem, StopToken(), observer));
    evaluations += result.evaluations;
    length = result.found ? PathLength(result.path) : 0.0;
  }
  state.counters["evals_per_cpu_s"] =
      benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kIsRate);
  state.counters["evals_per_run"] =
      benchmark::Counter(static_cast<double>(evaluations) / state.iterations());
  state.counters["length"] = length;
  static const char* const kLabel[] = {"paper, reference objective", "seeded, engine",
                                       "paper, engine"};
  state.SetLabel(kLabel[state.range(0)]);
}
BENCHMARK(BM_AemBsoEndToEnd)->Arg(0)->Arg(1)->Arg(2)->Iterations(2)->Unit(benchmark::kMillisecond);

// A streaming read of 256 MB: this machine's memory bandwidth (bytes per second).
void BM_StreamRead(benchmark::State& state) {
  std::vector<double> data(32 << 20, 1.0);
  for (auto _ : state) {
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (size_t i = 0; i + 3 < data.size(); i += 4) {
      s0 += data[i];
      s1 += data[i + 1];
      s2 += data[i + 2];
      s3 += data[i + 3];
    }
    benchmark::DoNotOptimize(s0 + s1 + s2 + s3);
  }
  state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(data.size() * sizeof(double)));
}
BENCHMARK(BM_StreamRead)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace swarmplan::bench
