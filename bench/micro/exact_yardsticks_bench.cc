// The exact yardsticks on the shared Moving AI maps: for each map, the exact any-angle optimum
// (AnyAngleSearch + OffsetTautPath, as the exact-any-angle planner runs them) against the
// octile optimum of the .scen file and against theta-star, with the time per query of each
// exact grid planner, and the per-map preprocessing. Reads the maps from
// $SWARMPLAN_MOVINGAI_DIR (default ../shared/benchmarks/movingai); registers nothing when the
// folder is absent. Times are thread CPU milliseconds per query. Run: swarmplan-microbench
// --benchmark_filter='ExactYardstick|AnyAngleGrid'
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/micro/fixtures.h"
#include "core/algorithms/exact/any_angle_grid.h"
#include "core/algorithms/exact/any_angle_search.h"
#include "core/algorithms/exact/taut_path_offset.h"
#include "core/geometry/grid_collision.h"
#include "core/graph/grid_search.h"
#include "core/graph/theta_star.h"
#include "core/map/io/map_io.h"

namespace swarmplan::bench {
namespace {

constexpr size_t kScenariosPerMap = 20;

// kScenariosPerMap scenarios spread evenly over the file (which runs from the shortest bucket
// to the longest).
std::vector<Scenario> EvenSample(const std::vector<Scenario>& scenarios) {
  std::vector<Scenario> sample;
  const size_t n = std::min(kScenariosPerMap, scenarios.size());
  for (size_t k = 0; k < n; ++k) {
    sample.push_back(scenarios[n == 1 ? 0 : k * (scenarios.size() - 1) / (n - 1)]);
  }
  return sample;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// CPU time of the calling thread, so that the figures hold on a loaded machine.
double ThreadCpuMilliseconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

template <class F>
double Milliseconds(F&& f) {
  const double start = ThreadCpuMilliseconds();
  f();
  return ThreadCpuMilliseconds() - start;
}

void RunYardstick(benchmark::State& state, const std::string& map_path) {
  absl::StatusOr<Map> map = LoadMapFile(map_path);
  absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(map_path + ".scen");
  if (!map.ok() || !scenarios.ok()) {
    state.SkipWithError("cannot load the map or its scenarios");
    return;
  }
  const OccupancyGrid& grid = *map->grid();
  const GridCollisionChecker checker(grid);
  const AnyAngleGrid any_angle = AnyAngleGrid::Build(grid, 0.0);
  const std::vector<Scenario> sample = EvenSample(*scenarios);
  GridSearchContext context;
  std::vector<double> exact_ms, theta_ms, astar_ms;
  double octile = 0, exact = 0, theta_ratio = 0, theta_ratio_max = 0, exact_over_octile = 0;
  int failures = 0;
  for (auto _ : state) {
    for (const Scenario& s : sample) {
      const Point2 start = grid.CellCenter(s.start), goal = grid.CellCenter(s.goal);
      double length = 0;
      exact_ms.push_back(Milliseconds([&] {
        const AnyAngleSearchResult r = AnyAngleSearch(any_angle, start, goal, nullptr);
        absl::StatusOr<std::vector<Point2>> path = OffsetTautPath(grid, r.vertices, 1e-7);
        if (!r.found || !path.ok()) return;
        for (size_t i = 0; i + 1 < path->size(); ++i)
          length += ((*path)[i + 1] - (*path)[i]).norm();
      }));
      GridSearchResult theta, astar;
      theta_ms.push_back(
          Milliseconds([&] { theta = ThetaStar(grid, checker, s.start, s.goal, {}, &context); }));
      astar_ms.push_back(
          Milliseconds([&] { astar = SearchGrid(grid, s.start, s.goal, {}, &context); }));
      if (length == 0 || !theta.found || !astar.found) {
        ++failures;
        continue;
      }
      octile += s.optimal_length;
      exact += length;
      exact_over_octile += length / s.optimal_length;
      theta_ratio += theta.length / length;
      theta_ratio_max = std::max(theta_ratio_max, theta.length / length);
    }
  }
  const double n = static_cast<double>(sample.size() - failures);
  state.counters["queries"] = static_cast<double>(sample.size());
  state.counters["failures"] = failures;
  state.counters["first_bucket"] = sample.front().bucket;
  state.counters["last_bucket"] = sample.back().bucket;
  state.counters["octile_mean"] = octile / n;
  state.counters["exact_mean"] = exact / n;
  state.counters["exact/octile"] = exact_over_octile / n;
  state.counters["theta/exact"] = theta_ratio / n;
  state.counters["theta/exact_max"] = theta_ratio_max;
  state.counters["exact_ms_median"] = Median(exact_ms);
  state.counters["exact_ms_max"] = *std::max_element(exact_ms.begin(), exact_ms.end());
  state.counters["theta_ms_median"] = Median(theta_ms);
  state.counters["astar_ms_median"] = Median(astar_ms);
}

void RunGridBuild(benchmark::State& state, const std::string& map_path, double clearance) {
  absl::StatusOr<Map> map = LoadMapFile(map_path);
  if (!map.ok()) {
    state.SkipWithError("cannot load the map");
    return;
  }
  int64_t bytes = 0;
  for (auto _ : state) {
    const AnyAngleGrid built = AnyAngleGrid::Build(*map->grid(), clearance);
    bytes = built.MemoryBytes();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}

// One benchmark per map: registered at start-up from the files present.
const bool registered = [] {
  const std::string dir = MovingAiDir();
  if (!std::filesystem::is_directory(dir)) return false;
  std::vector<std::string> maps;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".map" &&
        std::filesystem::exists(entry.path().string() + ".scen")) {
      maps.push_back(entry.path().string());
    }
  }
  std::sort(maps.begin(), maps.end());
  for (const std::string& path : maps) {
    const std::string name = std::filesystem::path(path).stem().string();
    benchmark::RegisterBenchmark(("ExactYardstick/" + name).c_str(),
                                 [path](benchmark::State& s) { RunYardstick(s, path); })
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
    for (const double clearance : {0.0, 1.0, 1.5}) {
      benchmark::RegisterBenchmark(
          ("AnyAngleGridBuild/" + name + "/clearance:" + std::to_string(clearance)).c_str(),
          [path, clearance](benchmark::State& s) { RunGridBuild(s, path, clearance); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace swarmplan::bench
