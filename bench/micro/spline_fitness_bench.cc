// The spline path fitness z = L (1 + M xi) of the waypoint planners (bso, aem-bso, pso, ba,
// bas on 2D maps): the hot path of those planners, and its parts.
//
// Maps (Arg 0): 0 = 100 x 100 world with 10 circles, 1 = with 30 circles, 2 = the 30-circle
// world rasterised to a 100 x 100 occupancy grid (xi from the distance field's labels).
// Arg 1: k, the free waypoints. Decision vectors are drawn around the straight start-goal line
// (band 30), like a swarm's positions, and cycled.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "bench/micro/fixtures.h"
#include "core/geometry/rasterize.h"
#include "core/map/generate.h"
#include "core/operators/obstacle_proximity.h"
#include "core/operators/waypoint_objective.h"
#include "core/operators/waypoint_path.h"
#include "core/random.h"

namespace swarmplan::bench {
namespace {

constexpr int kVectors = 1024;
constexpr double kSafeDistance = 1.5;

const MapPtr& FitnessMap(int which) {
  static const std::vector<MapPtr>* const maps = [] {
    const Bounds2 bounds{Point2(0, 0), Point2(100, 100)};
    const std::vector<Point2> keep = {Point2(10, 10), Point2(90, 90)};
    auto* out = new std::vector<MapPtr>();
    out->push_back(
        std::make_shared<const Map>(ValueOrDie(RandomShapeWorld(bounds, 10, 5, 10, 1, keep, 3))));
    ShapeWorld thirty = ValueOrDie(RandomShapeWorld(bounds, 30, 3, 7, 1, keep, 3));
    out->push_back(std::make_shared<const Map>(thirty));
    out->push_back(std::make_shared<const Map>(ValueOrDie(RasterizeShapeWorld(thirty, 1.0))));
    return out;
  }();
  return maps->at(which);
}

Problem FitnessProblem(int which) {
  Problem problem;
  problem.map = FitnessMap(which);
  problem.start = Point3(10, 10, 0);
  problem.goal = Point3(90, 90, 0);
  return problem;
}

WaypointFitnessOptions Options(int waypoints) {
  WaypointFitnessOptions options;
  options.waypoints = waypoints;
  options.d_safe = kSafeDistance;
  return options;
}

std::vector<Eigen::VectorXd> DecisionVectors(const WaypointObjective& objective) {
  Rng rng(7);
  std::vector<Eigen::VectorXd> xs(kVectors);
  for (Eigen::VectorXd& x : xs) objective.SampleAroundStraightPath(30.0, rng, x);
  return xs;
}

// The paths of DecisionVectors, decoded once.
std::vector<Path> DecodedPaths(WaypointObjective& objective) {
  std::vector<Path> paths;
  for (const Eigen::VectorXd& x : DecisionVectors(objective)) paths.push_back(objective.Decode(x));
  return paths;
}

void SetLabels(benchmark::State& state) {
  static const char* const kNames[] = {"10 circles", "30 circles", "grid 100x100"};
  state.SetLabel(kNames[state.range(0)]);
}

// The whole fitness, as the planners call it.
void BM_SplineFitness(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  auto objective = ValueOrDie(
      WaypointObjective::Create(FitnessProblem(which), Options(static_cast<int>(state.range(1)))));
  const std::vector<Eigen::VectorXd> xs = DecisionVectors(*objective);
  size_t i = 0;
  int feasible = 0;
  for (auto _ : state) {
    const Evaluation e = objective->Evaluate(xs[i]);
    feasible += e.feasible ? 1 : 0;
    benchmark::DoNotOptimize(e);
    i = (i + 1) % xs.size();
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["feasible"] = benchmark::Counter(feasible, benchmark::Counter::kAvgIterations);
  SetLabels(state);
}

// Part 1: fitting the spline through start, waypoints, goal and sampling its 100 points.
void BM_SplineBuild(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  auto objective = ValueOrDie(WaypointObjective::Create(FitnessProblem(which), Options(k)));
  const std::vector<Eigen::VectorXd> xs = DecisionVectors(*objective);
  const Problem problem = FitnessProblem(which);
  WaypointPathBuilder builder(problem.start, problem.goal, k, Interpolation::kSpline, 100);
  size_t i = 0;
  for (auto _ : state) {
    const Path& path = builder.Build(xs[i]);
    benchmark::DoNotOptimize(path.data());
    i = (i + 1) % xs.size();
  }
  state.SetItemsProcessed(state.iterations());
  SetLabels(state);
}

// Part 2: the length of the sampled polyline.
void BM_SampledLength(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  auto objective = ValueOrDie(WaypointObjective::Create(FitnessProblem(which), Options(k)));
  const std::vector<Path> paths = DecodedPaths(*objective);
  size_t i = 0;
  for (auto _ : state) {
    const Path& path = paths[i];
    double length = 0.0;
    for (size_t j = 0; j + 1 < path.size(); ++j) length += (path[j + 1] - path[j]).norm();
    benchmark::DoNotOptimize(length);
    i = (i + 1) % paths.size();
  }
  state.SetItemsProcessed(state.iterations());
  SetLabels(state);
}

// Part 3: xi, the obstacles closer than d_safe (segment-circle distances on a world, label
// lookups every quarter cell on a grid).
void BM_ClearanceCount(benchmark::State& state) {
  const int which = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  auto objective = ValueOrDie(WaypointObjective::Create(FitnessProblem(which), Options(k)));
  const std::vector<Path> paths = DecodedPaths(*objective);
  ObstacleProximity proximity =
      ValueOrDie(ObstacleProximity::Create(*FitnessMap(which), kSafeDistance));
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(proximity.CountViolations(paths[i]));
    i = (i + 1) % paths.size();
  }
  state.SetItemsProcessed(state.iterations());
  SetLabels(state);
}

void FitnessArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"map", "k"});
  for (int map = 0; map < 3; ++map) {
    for (int k : {2, 3, 5, 8}) b->Args({map, k});
  }
}

void BreakdownArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"map", "k"});
  for (int map = 0; map < 3; ++map) b->Args({map, 3});
}

BENCHMARK(BM_SplineFitness)->Apply(FitnessArgs);
BENCHMARK(BM_SplineBuild)->Apply(BreakdownArgs);
BENCHMARK(BM_SampledLength)->Apply(BreakdownArgs);
BENCHMARK(BM_ClearanceCount)->Apply(BreakdownArgs);

}  // namespace
}  // namespace swarmplan::bench
