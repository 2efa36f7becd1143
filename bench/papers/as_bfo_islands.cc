// AS-BFO paper (Long et al.): Table 4 (AS-BFO vs ACO vs GA on two island environments at five
// sizes), the parameter sweeps of its section 4.1 (P, Nc, Nre, Ned on S3) and its Morris analysis
// (section 4.2).

#include <algorithm>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "absl/time/time.h"
#include "bench/papers/as_bfo_islands_discussion.h"
#include "bench/papers/as_bfo_islands_morris.h"
#include "bench/papers/as_bfo_islands_replicated.h"
#include "bench/papers/as_bfo_islands_report.h"
#include "bench/papers/as_bfo_islands_runs.h"
#include "bench/papers/as_bfo_islands_significance.h"
#include "bench/papers/as_bfo_islands_sweep_tests.h"
#include "bench/papers/as_bfo_islands_times.h"
#include "bench/papers/as_bfo_islands_world.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/plan_once.h"
#include "bench/statistics.h"
#include "core/map/io/map_io.h"
#include "core/map/io/map_writers.h"

namespace swarmplan::bench {
namespace as_bfo_islands {

// Every method runs with the paper's initialisation (init=paper): the reproduction measures the
// paper's method, not the seeded one. AS-BFO and GA start from wandering initial paths (through up
// to kWanderingVia random cells), the near-A* rows (1 to kDefaultVia cells) are the ablation.
const std::vector<Method>& Methods() {
  static const std::vector<Method>* const methods = new std::vector<Method>{
      {"AS-BFO",
       "as-bfo",
       {{"init", std::string("paper")}, {"max_waypoints", int64_t{kWanderingVia}}},
       0},
      {"ACO", "aco-grid", {{"init", std::string("paper")}}, 1},
      {"GA", "ga", {{"init", std::string("paper")}, {"max_waypoints", int64_t{kWanderingVia}}}, 2},
      {"AS-BFO near-A*", "as-bfo", {{"init", std::string("paper")}}, -1},
      {"GA near-A*", "ga", {{"init", std::string("paper")}}, -1},
  };
  return *methods;
}

const std::vector<Sweep>& Sweeps() {
  static const std::vector<Sweep>* const sweeps = new std::vector<Sweep>{
      {"population",
       "P",
       {10, 20, 30, 40, 50, 60, 70, 80},
       "more bacteria converge faster (Fig. 6)",
       "more bacteria converge faster (Fig. 6)"},
      {"chemotactic_steps",
       "Nc",
       {1, 2, 3, 4, 5, 6, 7, 8},
       "shortest at Nc = 7, fewest at Nc = 8",
       "shortest at Nc = 8, fewest at Nc = 6",
       8,
       6},
      {"reproduction_steps",
       "Nre",
       {1, 2, 3, 4, 5},
       "shortest at Nre = 5, fewest at Nre = 4",
       "shortest at Nre = 2, fewest at Nre = 5",
       2,
       5},
      {"elimination_steps",
       "Ned",
       {1, 2, 3, 4, 5},
       "shortest at Ned = 3, fewest at Ned = 5",
       "shortest at Ned = 4, fewest at Ned = 4",
       4,
       4},
  };
  return *sweeps;
}

namespace {

constexpr int kTableRuns = 20;  // the paper's
constexpr int kSweepRuns = 20;
constexpr int kSweepSize = 20;  // the paper sweeps on S3
constexpr int kReplicatedRuns = 10;
// The drawn worlds run at the size the paper tunes on (S3) and at the largest, where it finds
// AS-BFO's advantage greatest (S5).
const std::vector<int>& ReplicatedSizes() {
  static const std::vector<int>* const sizes = new std::vector<int>{20, 30};
  return *sizes;
}
constexpr int kQuickReplicatedWorlds = 2;

void Log(const ExperimentOptions& options, const std::string& line) {
  if (options.log != nullptr) *options.log << line << "\n";
}

absl::StatusOr<World> LoadWorld(const std::string& worlds_dir, const std::string& environment,
                                int n, uint64_t seed) {
  const std::string path =
      absl::StrCat(worlds_dir, "/", kName, "/", IslandWorldFile(environment, n));
  absl::StatusOr<Map> map = LoadMapFile(path, "ascii");
  if (!map.ok()) return map.status();
  const OccupancyGrid* grid = map->grid();
  if (grid == nullptr || grid->width() != n || grid->height() != n) {
    return absl::FailedPreconditionError(absl::StrCat(path, ": not a ", n, " x ", n, " grid"));
  }
  absl::StatusOr<World> world = MakeWorld(environment, *grid, seed);
  if (!world.ok()) {
    return absl::Status(world.status().code(), absl::StrCat(path, ": ", world.status().message()));
  }
  return world;
}

}  // namespace

absl::StatusOr<std::string> Run(const ExperimentOptions& options) {
  const int table_runs = options.quick ? kQuickRuns : options.runs > 0 ? options.runs : kTableRuns;
  const int sweep_runs = options.quick ? kQuickRuns : options.runs > 0 ? options.runs : kSweepRuns;
  const int max_iterations = options.quick ? kQuickIterations : 0;
  const std::vector<int> sizes =
      options.quick ? std::vector<int>{AsBfoSizes().front()} : AsBfoSizes();

  std::vector<std::vector<World>> worlds;
  for (const IslandEnvironmentSpec& spec : AsBfoEnvironments()) {
    worlds.emplace_back();
    for (int n : sizes) {
      absl::StatusOr<World> world = LoadWorld(options.worlds_dir, spec.name, n, options.seed);
      if (!world.ok()) return world.status();
      worlds.back().push_back(*std::move(world));
    }
  }

  Table4 outcomes(worlds.size(), std::vector<std::vector<Outcome>>(Methods().size()));
  for (size_t e = 0; e < worlds.size(); ++e) {
    for (size_t m = 0; m < Methods().size(); ++m) {
      for (const World& world : worlds[e]) {
        PlanSpec spec{Methods()[m].algorithm, Methods()[m].params};
        spec.max_iterations = max_iterations;
        absl::StatusOr<Outcome> outcome = RunConfig(spec, world, table_runs, options.seed);
        if (!outcome.ok()) return outcome.status();
        Log(options, absl::StrFormat("%s %s %dx%d: %d/%d found, APL %s, %.1f ms/run",
                                     Methods()[m].label, world.environment, world.n, world.n,
                                     static_cast<int>(outcome->lengths.size()), outcome->runs,
                                     NumberCell(Mean(outcome->lengths)),
                                     Mean(outcome->millis).value_or(0.0)));
        outcomes[e][m].push_back(*std::move(outcome));
      }
    }
  }

  // The sweep world: S3 of the environment with more islands (the smallest size in quick mode).
  const World* sweep_world = &worlds.back().front();
  for (const World& w : worlds.back()) {
    if (w.n == kSweepSize) sweep_world = &w;
  }
  std::vector<SweepRow> sweep_rows;
  for (const Sweep& sweep : Sweeps()) {
    const std::vector<int> values =
        options.quick ? std::vector<int>{sweep.values.front()} : sweep.values;
    for (int value : values) {
      PlanSpec spec{
          "as-bfo",
          {{"init", std::string("paper")}, {sweep.parameter, static_cast<int64_t>(value)}}};
      spec.max_iterations = max_iterations;
      absl::StatusOr<Outcome> outcome = RunConfig(spec, *sweep_world, sweep_runs, options.seed);
      if (!outcome.ok()) return outcome.status();
      spec.params["max_waypoints"] = int64_t{kWanderingVia};
      absl::StatusOr<Outcome> wandering = RunConfig(spec, *sweep_world, sweep_runs, options.seed);
      if (!wandering.ok()) return wandering.status();
      Log(options,
          absl::StrFormat("sweep %s = %d: APL %s, %.1f ms/run", sweep.symbol, value,
                          NumberCell(Mean(outcome->lengths)), Mean(outcome->millis).value_or(0.0)));
      sweep_rows.push_back({&sweep, value, *std::move(outcome), *std::move(wandering)});
    }
  }

  // Section 4.2: the Morris analysis on S3 of each environment (the smallest size in quick mode).
  std::vector<MorrisAnalysis> morris;
  for (const std::vector<World>& environment : worlds) {
    const World* world = &environment.front();
    for (const World& w : environment) {
      if (w.n == kSweepSize) world = &w;
    }
    absl::StatusOr<MorrisAnalysis> analysis = RunMorris(
        *world, options.quick ? kQuickMorrisTrajectories : kMorrisTrajectories,
        options.quick ? kQuickRuns : kMorrisRuns, max_iterations, options.seed, options.jobs);
    if (!analysis.ok()) return analysis.status();
    Log(options,
        absl::StrFormat("Morris on %s %dx%d: done", world->environment, world->n, world->n));
    morris.push_back(*std::move(analysis));
  }

  // Table 4's methods of the paper on drawn worlds, AS-BFO first.
  const int replicated_worlds = options.quick ? kQuickReplicatedWorlds : kReplicatedWorlds;
  const int replicated_runs = options.quick      ? kQuickRuns
                              : options.runs > 0 ? options.runs
                                                 : kReplicatedRuns;
  std::vector<size_t> replicated_methods{kReferenceMethod};
  for (size_t m : TestedMethods()) replicated_methods.push_back(m);
  absl::StatusOr<std::vector<ReplicatedIslandCell>> replicated_runs_or =
      RunReplicatedIslands(replicated_methods, options.quick ? sizes : ReplicatedSizes(), options,
                           replicated_worlds, replicated_runs, max_iterations);
  if (!replicated_runs_or.ok()) return replicated_runs_or.status();
  const std::vector<ReplicatedIslandCell> replicated = *std::move(replicated_runs_or);
  std::string replicated_differences;

  std::string report =
      "# AS-BFO: Table 4, the sweeps of section 4.1 and the Morris analysis of section 4.2\n\n";
  absl::StrAppend(&report,
                  "Reproduces Long et al., *A*-based bacterial foraging optimisation for global "
                  "path planning of USVs* (seed 001): Table 4 (AS-BFO vs ACO vs GA on two island "
                  "environments at five grid sizes, 20 runs each), the sweeps of P, Nc, Nre "
                  "and Ned of its section 4.1 and its Morris analysis (section 4.2), with "
                  "`as-bfo`, `aco-grid`, `ga` and A* (`astar`) "
                  "for the optimum. Every found path is checked: it runs from start to goal in "
                  "8-connected moves without corner cutting, is collision-free and is not "
                  "shorter than A*'s optimum.\n\n");
  absl::StrAppend(&report, SettingsSection(options, table_runs, sweep_runs, sizes));
  absl::StrAppend(&report, WorldsSection(worlds));
  absl::StrAppend(&report, Table4Section(worlds, outcomes));
  absl::StrAppend(&report, Table4Summary(worlds, outcomes));
  absl::StrAppend(&report, Table4TestsSection(worlds, outcomes));
  absl::StrAppend(&report, ReplicatedIslandsSection(replicated, replicated_methods, replicated_runs,
                                                    options.seed, &replicated_differences));
  absl::StrAppend(&report, SweepSection(*sweep_world, sweep_rows, sweep_runs));
  const std::vector<SweepEnds> sweep_ends = SweepEndsOf(sweep_rows, sweep_world->optimum);
  absl::StrAppend(&report, SweepTestsSection(sweep_ends, sweep_world->optimum));
  absl::StrAppend(&report,
                  MorrisSection(morris, options.quick ? kQuickRuns : kMorrisRuns, options.seed));
  absl::StrAppend(&report, Discussion({worlds, outcomes, *sweep_world, sweep_rows, sweep_ends,
                                       morris, replicated_worlds, replicated_runs,
                                       replicated_differences, options.quick}));
  absl::StrAppend(&report, RunTimesSection(worlds, outcomes, sweep_rows));
  return report;
}

absl::Status Generate(const std::string& dir) {
  for (const IslandEnvironmentSpec& spec : AsBfoEnvironments()) {
    absl::StatusOr<IslandLayout> layout = AcceptedIslands(spec, AsBfoSizes());
    if (!layout.ok()) return layout.status();
    for (int n : AsBfoSizes()) {
      absl::StatusOr<OccupancyGrid> grid = RasteriseIslands(layout->discs, n, spec.obstacle_ratio);
      if (!grid.ok()) return grid.status();
      const std::string path = absl::StrCat(dir, "/", IslandWorldFile(spec.name, n));
      std::ofstream out(path, std::ios::binary);
      out << FormatAsciiMap(*grid);
      if (!out) return absl::InternalError(absl::StrCat("cannot write ", path));
    }
  }
  return absl::OkStatus();
}

}  // namespace as_bfo_islands

absl::StatusOr<std::string> RunAsBfoIslands(const ExperimentOptions& options) {
  return as_bfo_islands::Run(options);
}

absl::Status GenerateAsBfoIslands(const std::string& dir) { return as_bfo_islands::Generate(dir); }

}  // namespace swarmplan::bench
