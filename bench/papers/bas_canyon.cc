// BAS paper (seed 000), section IV.A: ACO, BAS, LFS-BAS and ACO-BAS on a 3D canyon (its Table 2 /
// Fig. 4, Table 3 and Fig. 6), SIO-BAS against Multi-BAS (its Table 4), two step options of ours
// for the paper's beetles, and the headline comparisons on ten generated canyons.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "bench/papers/bas_canyon_2d.h"
#include "bench/papers/bas_canyon_discussion.h"
#include "bench/papers/bas_canyon_paper.h"
#include "bench/papers/bas_canyon_replicated.h"
#include "bench/papers/bas_canyon_runs.h"
#include "bench/papers/bas_canyon_setup.h"
#include "bench/papers/bas_canyon_significance.h"
#include "bench/papers/bas_canyon_sweeps.h"
#include "bench/papers/bas_canyon_tables.h"
#include "bench/papers/bas_canyon_terrain.h"
#include "bench/papers/bas_canyon_world.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/world_replication.h"

namespace swarmplan::bench {
namespace {

using bas::ClaimedPair;
using bas::Row;
using bas::RowSet;
using bas::Spec;

constexpr int kDefaultRuns = 30;
constexpr int kQuickRuns = 2;
constexpr int kQuickIterations = 10;
constexpr int kQuickReplicatedWorlds = 2;
constexpr int kReplicatedRuns = 10;
constexpr int kPaper2dIterations = 100;  // Fig. 11's BAS
// Table D's map-scaled step: a twentieth of each range, one cell of the canyon's 20 in Y.
constexpr double kMapStepFraction = 0.05;
const char* const kBeetles[] = {"bas", "lfs-bas", "aco-bas", "sio-bas", "multi-bas"};

std::string AcoLabel(int iterations) { return absl::StrCat("aco (", iterations, " iterations)"); }

// The paper's beetle settings for `planner` (its Table B population where it has one).
ParamValues BeetleParams(const std::string& planner, int iterations, int population_iterations) {
  const bool population = planner == "sio-bas" || planner == "multi-bas";
  ParamValues params = bas::PaperBeetleParams(population ? population_iterations : iterations);
  if (population) params["population"] = int64_t{bas::kPaperPopulation};
  if (planner == "aco-bas") params["ants"] = int64_t{20};
  return params;
}

ParamValues SmallStep(ParamValues params) {
  params["step0"] = 1.0;
  return params;
}

std::vector<Row> TableARows(int iterations) {
  return {{"aco", Spec("aco", bas::PaperAcoParams(iterations))},
          {"bas", Spec("bas", BeetleParams("bas", iterations, 0))},
          {"lfs-bas", Spec("lfs-bas", BeetleParams("lfs-bas", iterations, 0))},
          {"aco-bas", Spec("aco-bas", BeetleParams("aco-bas", iterations, 0))},
          {"bas, δ0 = 1 (ablation)", Spec("bas", SmallStep(BeetleParams("bas", iterations, 0)))},
          {"aco-bas, δ0 = 1 (ablation)",
           Spec("aco-bas", SmallStep(BeetleParams("aco-bas", iterations, 0)))}};
}

std::vector<Row> TableBRows(int iterations) {
  return {{"sio-bas", Spec("sio-bas", BeetleParams("sio-bas", 0, iterations))},
          {"multi-bas", Spec("multi-bas", BeetleParams("multi-bas", 0, iterations))},
          {AcoLabel(iterations), Spec("aco", bas::PaperAcoParams(iterations))},
          {"sio-bas, δ0 = 1 (ablation)",
           Spec("sio-bas", SmallStep(BeetleParams("sio-bas", 0, iterations)))},
          {"multi-bas, δ0 = 1 (ablation)",
           Spec("multi-bas", SmallStep(BeetleParams("multi-bas", 0, iterations)))}};
}

std::vector<Row> TableCRows(int iterations) {
  std::vector<Row> rows;
  for (const double step0 : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    ParamValues params = BeetleParams("bas", iterations, 0);
    params["step0"] = step0;
    rows.push_back({absl::StrCat("bas, δ0 = ", step0), Spec("bas", std::move(params))});
  }
  return rows;
}

std::string RejectLabel(const std::string& planner) {
  return absl::StrCat(planner, ", reject infeasible");
}
std::string MapLabel(const std::string& planner) { return absl::StrCat(planner, ", map steps"); }
std::string BothLabel(const std::string& planner) {
  return absl::StrCat(planner, ", map steps + reject");
}

std::vector<Row> TableDRows(int iterations, int population_iterations) {
  std::vector<Row> rows;
  for (const char* planner : kBeetles) {
    const ParamValues paper = BeetleParams(planner, iterations, population_iterations);
    rows.push_back({RejectLabel(planner), Spec(planner, bas::RejectInfeasible(paper))});
    rows.push_back(
        {MapLabel(planner), Spec(planner, bas::MapScaledSteps(paper, kMapStepFraction))});
    rows.push_back({BothLabel(planner), Spec(planner, bas::RejectInfeasible(bas::MapScaledSteps(
                                                          paper, kMapStepFraction)))});
  }
  return rows;
}

std::vector<ClaimedPair> HeadlinePairs(int population_iterations) {
  const std::string aco_b = AcoLabel(population_iterations);
  return {{"aco", "bas", "paper: BAS beats ACO (Fig. 4)"},
          {"aco", "lfs-bas", "paper: LFS-BAS beats ACO"},
          {"aco", "aco-bas", "paper: ACO-BAS beats ACO"},
          {"bas", "lfs-bas", "paper: LFS-BAS beats BAS"},
          {"bas", "aco-bas", "paper: ACO-BAS beats BAS"},
          {"multi-bas", "sio-bas", "paper: SIO-BAS beats Multi-BAS (Table 4)"},
          {aco_b, "sio-bas", "paper: SIO-BAS beats ACO at 200 iterations"},
          {aco_b, "multi-bas", "paper: Multi-BAS beats ACO at 200 iterations"}};
}

// Per beetle and option: against the same beetle at the paper's settings, and against ACO.
std::vector<ClaimedPair> OptionPairs(int population_iterations) {
  std::vector<ClaimedPair> pairs;
  for (const char* planner : kBeetles) {
    const bool population =
        std::string(planner) == "sio-bas" || std::string(planner) == "multi-bas";
    const std::string aco = population ? AcoLabel(population_iterations) : "aco";
    for (const std::string& label : {RejectLabel(planner), MapLabel(planner), BothLabel(planner)}) {
      pairs.push_back({planner, label, "the option lowers the fitness"});
    }
    pairs.push_back({aco, BothLabel(planner), "with both options it beats ACO"});
  }
  return pairs;
}

std::vector<Row> ReplicatedRows(int iterations, int population_iterations) {
  std::vector<Row> rows = {
      {AcoLabel(population_iterations), Spec("aco", bas::PaperAcoParams(population_iterations))}};
  for (const char* planner : kBeetles) {
    rows.push_back(
        {planner, Spec(planner, BeetleParams(planner, iterations, population_iterations))});
  }
  rows.push_back({BothLabel("lfs-bas"),
                  Spec("lfs-bas", bas::RejectInfeasible(bas::MapScaledSteps(
                                      BeetleParams("lfs-bas", iterations, 0), kMapStepFraction)))});
  return rows;
}

std::vector<ClaimedPair> ReplicatedPairs(int population_iterations) {
  const std::string aco = AcoLabel(population_iterations);
  return {{aco, "bas", "paper: BAS beats ACO"},
          {aco, "lfs-bas", "paper: LFS-BAS beats ACO"},
          {aco, "aco-bas", "paper: ACO-BAS beats ACO"},
          {aco, "sio-bas", "paper: SIO-BAS beats ACO"},
          {"multi-bas", "sio-bas", "paper: SIO-BAS beats Multi-BAS"},
          {aco, BothLabel("lfs-bas"), "ours: LFS-BAS with both options beats ACO"}};
}

}  // namespace

absl::StatusOr<std::string> RunBasCanyon(const ExperimentOptions& options) {
  const double lattice_step =
      options.quick ? bas::kQuickLatticeVerticalStep : bas::kLatticeVerticalStep;
  const CanyonShape shape;
  absl::StatusOr<bas::CanyonWorld> world =
      bas::LoadShippedCanyon(options.worlds_dir, shape.mouth_y, lattice_step);
  if (!world.ok()) return world.status();
  absl::StatusOr<bas::CanyonWorld> moved =
      bas::LoadShippedCanyon(options.worlds_dir, bas::MovedStartY(), lattice_step);
  if (!moved.ok()) return moved.status();

  const int iterations = options.quick ? kQuickIterations : bas::kPaperIterations;
  const int population_iterations =
      options.quick ? kQuickIterations : bas::kPaperPopulationIterations;
  const int runs = options.quick ? kQuickRuns : (options.runs > 0 ? options.runs : kDefaultRuns);
  const int sweep_runs = options.quick ? kQuickRuns : std::min(runs, bas::kPaperRuns);
  const int replicated_worlds = options.quick ? kQuickReplicatedWorlds : kReplicatedWorlds;
  const int replicated_runs = options.quick ? kQuickRuns : std::min(runs, kReplicatedRuns);
  const int iterations_2d = options.quick ? kQuickIterations : kPaper2dIterations;

  const std::vector<Row> rows_a = TableARows(iterations);
  const std::vector<Row> rows_b = TableBRows(population_iterations);
  const std::vector<Row> rows_c = TableCRows(iterations);
  const std::vector<Row> rows_d = TableDRows(iterations, population_iterations);
  const std::vector<int> sweep_iterations = bas::SweepIterations(options.quick);
  absl::StatusOr<RowSet> a = bas::RunRows(rows_a, *world, options, runs);
  if (!a.ok()) return a.status();
  absl::StatusOr<RowSet> b = bas::RunRows(rows_b, *world, options, runs);
  if (!b.ok()) return b.status();
  absl::StatusOr<RowSet> c = bas::RunRows(rows_c, *world, options, runs);
  if (!c.ok()) return c.status();
  absl::StatusOr<RowSet> d = bas::RunRows(rows_d, *world, options, runs);
  if (!d.ok()) return d.status();
  absl::StatusOr<RowSet> sweep =
      bas::RunRows(bas::IterationSweepRows(sweep_iterations), *world, options, sweep_runs);
  if (!sweep.ok()) return sweep.status();
  absl::StatusOr<RowSet> moved_runs =
      bas::RunRows(bas::MovedStartRows(iterations), *moved, options, sweep_runs);
  if (!moved_runs.ok()) return moved_runs.status();
  absl::StatusOr<std::vector<bas::ReplicatedWorld>> replicated =
      bas::RunReplicatedCanyons(ReplicatedRows(iterations, population_iterations), options,
                                replicated_worlds, replicated_runs, lattice_step);
  if (!replicated.ok()) return replicated.status();

  const RowSet shipped = bas::Merged(bas::Merged(*a, *b), bas::Merged(*c, *d));
  const std::vector<bas::PairTest> headline =
      bas::TestPairs(shipped, HeadlinePairs(population_iterations));
  const std::vector<bas::PairTest> option_tests =
      bas::TestPairs(shipped, OptionPairs(population_iterations));
  const std::vector<bas::PairTest> sweep_tests =
      bas::TestPairs(*sweep, bas::IterationSweepPairs(sweep_iterations));
  const std::vector<bas::ReplicatedPairTest> replicated_tests =
      bas::TestReplicatedPairs(*replicated, ReplicatedPairs(population_iterations));

  bas::SetupFigures figures;
  figures.iterations = iterations;
  figures.population_iterations = population_iterations;
  figures.runs = runs;
  figures.sweep_runs = sweep_runs;
  figures.replicated_worlds = replicated_worlds;
  figures.replicated_runs = replicated_runs;
  figures.map_step_fraction = kMapStepFraction;
  figures.first_seed = options.seed;

  std::string report = absl::StrCat(
      "# BAS paper: canyon terrain (Fig. 4 / Tables 2-4, Fig. 6)\n\n"
      "Reproduces section IV.A of the improved Beetle Antennae Search paper (seed 000): ACO, "
      "BAS, LFS-BAS and ACO-BAS planning through a 3D canyon (its Fig. 4 and Table 2), their "
      "iteration sweep (Table 3) and a moved start (Fig. 6), then SIO-BAS against Multi-BAS "
      "(its Table 4); the paper's beetles with infeasible moves undone and steps scaled to the "
      "map (Table D, ours), and the headline comparisons on ",
      replicated_worlds,
      " generated canyons; then its 2D experiments (Figs. 10-11). Generated by "
      "`swarmplan-papers run bas-canyon`",
      options.quick ? " in quick mode (2 runs, 10 iterations: the numbers say nothing)" : "",
      ".\n\n", bas::SetupSection(*world, figures));
  absl::StrAppend(&report, "## Table A: ACO, BAS, LFS-BAS, ACO-BAS (paper's Fig. 4 / Table 2)\n\n",
                  bas::YardstickParagraph(*world), bas::FitnessTable(*a, world->lattice.cost),
                  "\n");
  absl::StrAppend(&report, "## Table B: SIO-BAS vs Multi-BAS (paper's Table 4)\n\n",
                  bas::FitnessTable(*b, world->lattice.cost), "\n");
  absl::StrAppend(&report, "## Significance of the paper's claims (Tables A and B)\n\n",
                  bas::SignificanceTable(shipped, headline), "\n");
  absl::StrAppend(&report,
                  "## Table C (ours): BAS's initial step δ0\n\n"
                  "bas with the paper's settings except δ0 (δ and θ decay as above, d = δ / c); "
                  "δ0 = 8 is Table A's bas.\n\n",
                  bas::FitnessTable(*c, world->lattice.cost), "\n");
  absl::StrAppend(
      &report,
      "## Table D (ours): the paper's beetles with infeasible moves undone and steps scaled "
      "to the map\n\n"
      "Each beetle with the paper's settings (Tables A and B) plus `reject_infeasible=true`, "
      "plus `step_units=map` (step_fraction ",
      kMapStepFraction, "), or both.\n\n", bas::FitnessTable(*d, world->lattice.cost),
      "\nTests: each option against the same beetle at the paper's settings, and both options "
      "against ACO (Table A's for the single beetles, Table B's for the populations).\n\n",
      bas::SignificanceTable(shipped, option_tests), "\n");
  absl::StrAppend(&report, "## Table 3: iterations (paper's Table 3 / Fig. 5)\n\n",
                  bas::FitnessTable(*sweep, world->lattice.cost), "\n",
                  bas::SignificanceTable(*sweep, sweep_tests), "\n");
  absl::StrAppend(&report, "## Fig. 6: moved start\n\n",
                  "Start at the first column, y = ", bas::MovedStartY(),
                  "; lattice yardstick from there: ", NumberCell(moved->lattice.cost), ".\n\n",
                  bas::FitnessTable(*moved_runs, moved->lattice.cost), "\n");
  absl::StrAppend(&report, "## Replication over ", replicated_worlds, " canyons\n\n",
                  "World 0 is the shipped canyon; world r is drawn from seed ", bas::kCanyonSeed,
                  " + ", kWorldSeedStride, " r. ACO runs ", population_iterations,
                  " iterations (Table 3: no better at 500). ", replicated_runs,
                  " runs per planner and world.\n\n",
                  bas::ReplicatedSection(*replicated, replicated_tests), "\n");
  absl::StatusOr<std::string> two_d = bas::TwoDSection(options, runs, iterations_2d);
  if (!two_d.ok()) return two_d.status();
  absl::StrAppend(&report, *two_d);
  bas::DiscussionInputs discussion;
  discussion.shipped = shipped;
  discussion.yardstick = world->lattice.cost;
  for (const char* planner : kBeetles) discussion.paper_setting_labels.push_back(planner);
  discussion.headline = headline;
  discussion.options = option_tests;
  discussion.sweep = sweep_tests;
  discussion.sweep_set = *sweep;
  for (const Row& row : rows_c) discussion.step_labels.push_back(row.label);
  discussion.moved_start = bas::TestMovedStart(*moved_runs);
  discussion.replicated = replicated_tests;
  discussion.replicated_worlds = replicated_worlds;
  discussion.dimensions = 2 * (shape.width - 2);
  absl::StrAppend(&report, bas::Discussion(discussion), "\n");
  absl::StrAppend(
      &report,
      "## Time per run\n\n"
      "Wall times on a shared, loaded 2-core machine, beside the paper's (its Fig. 4 and 6-7 "
      "captions and text); compare ratios, not seconds.\n\n",
      bas::TimeTable(bas::Merged(bas::Merged(shipped, *sweep), *moved_runs)), "\n",
      bas::TimeRatioSentence(shipped, "aco", "bas"), "\n");
  return report;
}

absl::Status GenerateBasCanyon(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / bas::kCanyonFile).string();
  std::ofstream out(path, std::ios::binary);
  out << bas::CanyonAscText(bas::kCanyonSeed);
  out.close();
  if (!out) return absl::InternalError(absl::StrCat("bas-canyon: cannot write ", path));
  return absl::OkStatus();
}

}  // namespace swarmplan::bench
