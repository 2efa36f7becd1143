// The seed search of the seeded planners (FindSeedPaths: the exact optimum, then each next
// corridor's) on the longest scenario of the large shared Moving AI maps, with the fleet
// settings of bench/results/real-maps.md (clearance 0.5, preferred clearance 1.5, three seeds).
// "cold" plans on a map loaded anew, so the time includes the map's own clearance grids; "warm"
// on a map whose grids an earlier plan built, as every later plan on a stored map. Reads the
// maps from $SWARMPLAN_MOVINGAI_DIR (default ../shared/benchmarks/movingai); registers nothing
// when the folder is absent. Run: swarmplan-microbench --benchmark_filter=SeedPaths
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/micro/fixtures.h"
#include "core/map/io/map_io.h"
#include "core/problem.h"
#include "core/seeds/seed_paths.h"

namespace swarmplan::bench {
namespace {

absl::StatusOr<Problem> LongestProblem(const std::string& map_path) {
  absl::StatusOr<Map> map = LoadMapFile(map_path);
  if (!map.ok()) return map.status();
  absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(map_path + ".scen");
  if (!scenarios.ok()) return scenarios.status();
  if (scenarios->empty()) return absl::NotFoundError("no scenarios");
  const Scenario& longest = scenarios->back();
  Problem problem;
  problem.map = std::make_shared<const Map>(*std::move(map));
  problem.start = Point3(longest.start.x + 0.5, longest.start.y + 0.5, 0.0);
  problem.goal = Point3(longest.goal.x + 0.5, longest.goal.y + 0.5, 0.0);
  problem.clearance = 0.5;
  problem.fleet.preferred_clearance = 1.5;
  problem.fleet.turning_radius = 2.0;
  return problem;
}

void RunSeedPaths(benchmark::State& state, const std::string& map_path, bool warm) {
  absl::StatusOr<Problem> problem = LongestProblem(map_path);
  if (!problem.ok()) {
    state.SkipWithError("cannot load the map or its scenarios");
    return;
  }
  size_t seeds = 0;
  if (warm) FindSeedPaths(*problem, 3, StopToken()).IgnoreError();
  for (auto _ : state) {
    if (!warm) {
      state.PauseTiming();
      problem->map = std::make_shared<const Map>(Map::Data(*problem->map->grid()));
      state.ResumeTiming();
    }
    absl::StatusOr<std::vector<SeedPath>> found = FindSeedPaths(*problem, 3, StopToken());
    seeds = found.ok() ? found->size() : 0;
    benchmark::DoNotOptimize(seeds);
  }
  state.counters["seeds"] = static_cast<double>(seeds);
}

// Registered at start-up for the large maps present.
const bool registered = [] {
  const std::string dir = MovingAiDir();
  for (const std::string name :
       {"random512-10-0", "maze512-32-9", "AcrosstheCape", "Berlin_0_256", "den312d"}) {
    const std::string path = dir + "/" + name + ".map";
    if (!std::filesystem::exists(path) || !std::filesystem::exists(path + ".scen")) continue;
    for (const bool warm : {false, true}) {
      benchmark::RegisterBenchmark(
          ("SeedPaths/" + name + (warm ? "/warm" : "/cold")).c_str(),
          [path, warm](benchmark::State& s) { RunSeedPaths(s, path, warm); })
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace swarmplan::bench
