// AEM-BSO paper, Tables 2-3: path planning on a 100 x 100 world with 10 ("simple") and 30
// ("complex") circles, aem-bso with three interpolations and the four planners with the spline,
// next to the exact visibility-graph optimum.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/aem_bso_worlds_discussion.h"
#include "bench/papers/aem_bso_worlds_figures.h"
#include "bench/papers/aem_bso_worlds_generate.h"
#include "bench/papers/aem_bso_worlds_paper.h"
#include "bench/papers/aem_bso_worlds_replicated.h"
#include "bench/papers/aem_bso_worlds_runs.h"
#include "bench/papers/aem_bso_worlds_variants.h"
#include "bench/papers/aem_bso_worlds_world_run.h"
#include "bench/papers/comparison.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/plan_once.h"
#include "bench/significance.h"
#include "bench/statistics.h"
#include "core/map/io/map_io.h"
#include "core/map/io/map_writers.h"

namespace swarmplan::bench {
namespace {

using aem_bso::AemBsoGoal;
using aem_bso::AemBsoStart;
using aem_bso::AemBsoWorldSpec;
using aem_bso::AemBsoWorldSpecs;
using aem_bso::CellStats;
using aem_bso::ExactOptimum;
using aem_bso::Interpolations;
using aem_bso::kAemBsoSafeDistance;
using aem_bso::kPopulation;
using aem_bso::PaperCell;
using aem_bso::PaperPlan;
using aem_bso::PaperTable2;
using aem_bso::PaperTable3;
using aem_bso::Planners;
using aem_bso::RunCell;
using aem_bso::WorldRun;

constexpr int kDefaultRuns = 30;
constexpr int kIterations = 500;
constexpr int kQuickRuns = 2;
constexpr int kQuickIterations = 20;
constexpr int kReplicatedRuns = 10;  // per world of the ten-world Table 3
constexpr int kQuickReplicatedWorlds = 2;

absl::StatusOr<WorldRun> RunWorld(const AemBsoWorldSpec& spec, const ExperimentOptions& options,
                                  int runs, int iterations) {
  const std::string path =
      (std::filesystem::path(options.worlds_dir) / "aem-bso-worlds" / spec.file).string();
  absl::StatusOr<Map> loaded = LoadMapFile(path, "shapes-json");
  if (!loaded.ok()) return loaded.status();
  const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
  WorldRun out;
  out.spec = spec;
  out.straight = (AemBsoGoal() - AemBsoStart()).norm();
  absl::StatusOr<double> optimum = ExactOptimum(map, options.seed, path);
  if (!optimum.ok()) return optimum.status();
  out.optimum = *optimum;

  for (const std::string& planner : Planners()) {
    for (const std::string& interpolation : Interpolations()) {
      absl::StatusOr<CellStats> cell =
          RunCell(PaperPlan(planner, interpolation, iterations), map, options, runs,
                  absl::StrCat(spec.name, " ", planner, "/", interpolation));
      if (!cell.ok()) return cell.status();
      out.cells[{planner, interpolation}] = *std::move(cell);
    }
  }
  absl::StatusOr<aem_bso::VariantRuns> variants =
      aem_bso::RunVariants(spec.name, map, options, runs, iterations);
  if (!variants.ok()) return variants.status();
  out.variants = *std::move(variants);
  return out;
}

std::optional<double> Ratio(std::optional<double> value, double optimum) {
  if (!value.has_value() || optimum <= 0) return std::nullopt;
  return *value / optimum;
}

std::string PaperNumber(const std::optional<PaperCell>& cell,
                        std::optional<double> PaperCell::*field) {
  return cell.has_value() ? NumberCell(cell.value().*field) : "";
}

std::vector<std::string> OurCells(const CellStats& cell, double optimum) {
  return {PercentCell(cell.runs > 0 ? static_cast<double>(cell.lengths.size()) / cell.runs : 0.0),
          NumberCell(Min(cell.lengths)),
          NumberCell(Mean(cell.lengths)),
          NumberCell(StdDev(cell.lengths)),
          NumberCell(Mean(cell.fitnesses)),
          NumberCell(Ratio(Min(cell.lengths), optimum), 4),
          NumberCell(Ratio(Mean(cell.lengths), optimum), 4),
          NumberCell(Mean(cell.best_iterations), 3),
          NumberCell(Mean(cell.seconds), 3),
          NumberCell(Mean(cell.cpu_seconds), 3)};
}

const std::vector<std::string>& OurHeader() {
  static const std::vector<std::string>* const header = new std::vector<std::string>{
      "found",          "shortest",   "mean",      "std",   "mean z (all runs)",
      "shortest / opt", "mean / opt", "best iter", "s/run", "CPU s/run"};
  return *header;
}

std::string FoundCell(const CellStats& cell) {
  return absl::StrCat(cell.lengths.size(), "/", cell.runs);
}

// aem-bso with the spline against each planner with the spline, and the significant
// differences per world, e.g. "simple: pso's z higher (p = 0.003); complex: none".
std::string SignificanceSection(const std::vector<WorldRun>& worlds, std::string* summary) {
  std::string out = "## Significance: aem-bso against each planner (spline)\n\n";
  absl::StrAppend(
      &out,
      "The same seeds for every planner. *found*: runs that found a path, compared by Fisher's "
      "exact test; *z*: the fitness of every run, penalty included, and *length*: of the runs "
      "that found a path, each compared by the Mann-Whitney rank-sum test (two-sided); medians "
      "with bootstrap 95 % intervals (10,000 resamples). * marks p < 0.05, a difference larger "
      "than the scatter of the runs explains.\n\n");
  MarkdownTable table({"environment", "planner", "found", "Fisher", "median z", "rank-sum (z)",
                       "median length", "rank-sum (length)"},
                      2);
  for (const WorldRun& w : worlds) {
    const CellStats& aem = w.cells.at({"aem-bso", "spline"});
    std::string differences;
    for (const std::string& planner : Planners()) {
      const CellStats& cell = w.cells.at({planner, "spline"});
      if (planner == "aem-bso") {
        table.AddRow({w.spec.name, planner, FoundCell(cell), "", MedianWithInterval(cell.fitnesses),
                      "", MedianWithInterval(cell.lengths), ""});
        continue;
      }
      const std::optional<double> found_p = SuccessP(aem.Found(), cell.Found());
      const std::optional<double> z_p = RankSumP(aem.fitnesses, cell.fitnesses);
      const std::optional<double> length_p = RankSumP(aem.lengths, cell.lengths);
      table.AddRow({w.spec.name, planner, FoundCell(cell), PValueCell(found_p),
                    MedianWithInterval(cell.fitnesses), PValueCell(z_p),
                    MedianWithInterval(cell.lengths), PValueCell(length_p)});
      AppendListItem(&differences, SuccessDifference(planner, aem.Found(), cell.Found(), found_p));
      AppendListItem(&differences,
                     ValueDifference(planner, "z", aem.fitnesses, cell.fitnesses, z_p));
      AppendListItem(&differences,
                     ValueDifference(planner, "length", aem.lengths, cell.lengths, length_p));
    }
    absl::StrAppend(summary, summary->empty() ? "" : "; ", w.spec.name, ": ",
                    differences.empty() ? "none" : differences);
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  return out;
}

// The ten-world Table 3 and what of it the tests support.
struct Replication {
  std::vector<aem_bso::ReplicatedEnvironment> environments;
  int runs = 0;
};

std::string Report(const std::vector<WorldRun>& worlds, const Replication& replication,
                   const ExperimentOptions& options, int runs, int iterations) {
  std::string out = "# AEM-BSO Tables 2-3: path planning on 100 x 100 worlds with circles\n\n";
  absl::StrAppend(
      &out,
      "Reproduces Tables 2 and 3 of Ouyang, Kuang, Ye, *Path planning based on improved beetle "
      "swarm optimization algorithm and cubic spline interpolation* (seed 002, section 5), with "
      "`swarmplan-papers run aem-bso-worlds`",
      options.quick ? " **in quick mode (its numbers say nothing about the planners)**" : "",
      ".\n\n");
  absl::StrAppend(&out, "## Settings\n\n");
  absl::StrAppend(
      &out,
      "| setting | paper | ours |\n|---|---|---|\n"
      "| map | 100 x 100, start (10, 10), goal (90, 90) | same |\n"
      "| obstacles | 10 (simple) and 30 (complex) circles, not published | drawn, seeded, "
      "shipped in `bench/worlds/aem-bso-worlds/` (below) |\n"
      "| fitness | z = L (1 + M xi), M = 100, d_safe = 1.5 | same (`penalty` = 100, `d_safe` = "
      "1.5; the problem's clearance is 1.5 too, so xi = 0 is exactly \"found\") |\n",
      absl::StrFormat("| population | 100 | %d |\n", kPopulation),
      absl::StrFormat("| iterations | 500 | %d |\n", iterations),
      absl::StrFormat("| runs per cell | 100 | %d (seeds %d..%d) |\n", runs, options.seed,
                      options.seed + runs - 1),
      "| waypoints m | not given | 3 (the planners' default: decision vector of 6) |\n"
      "| spline samples n | not given | 100 (not-a-knot, uniform parameter, like MATLAB "
      "`spline`) |\n"
      "| w_max, w_min, c1..c3 | 0.9, 0.4, 1.49 (PSO: c1 = c2 = 1.49) | same (PSO's own default "
      "c1 = c2 = 2 is overridden) |\n"
      "| BA | parameters not given | our `ba` defaults (f in [0, 2], A0 = 1, r0 = 0.5, alpha = "
      "gamma = 0.9, pulse rate set on accept, no velocity bound) |\n"
      "| k1, k2, k3 (elite mutation) | not given | 0.1, 0.1, -1 (ours) |\n"
      "| yardstick | none | exact shortest path keeping 1.5 (`visibility-graph`, circle "
      "tolerance 0.01) |\n\n");
  absl::StrAppend(
      &out,
      "*Shortest / mean / std* are path lengths over the runs that found a path (xi = 0: the "
      "sampled path keeps 1.5 from every circle and stays in the map); *mean z* is the mean "
      "fitness over all runs, penalty included (the paper's means are of lengths: see the "
      "discussion). *best iter*: mean iteration at which the final best was found. *s/run* "
      "is wall time, *CPU s/run* the planning thread's CPU time, per run, on a shared, loaded "
      "2-core machine running other jobs: compare ratios between rows, not with the paper's "
      "MATLAB seconds.\n\n");

  absl::StrAppend(&out, "## Worlds and the exact optimum\n\n");
  MarkdownTable worlds_table({"environment", "file", "circles", "radii", "straight line",
                              "optimum keeping 1.5", "optimum / straight"});
  for (const WorldRun& w : worlds) {
    worlds_table.AddRow({w.spec.name, "`" + w.spec.file + "`", absl::StrCat(w.spec.circles),
                         absl::StrFormat("U[%g, %g]", w.spec.min_radius, w.spec.max_radius),
                         NumberCell(w.straight), NumberCell(w.optimum),
                         NumberCell(w.optimum / w.straight, 4)});
  }
  absl::StrAppend(&out, worlds_table.ToString(), "\n");
  absl::StrAppend(
      &out,
      "Circles are drawn by `RandomShapeWorld` (core/map/generate.h) from seed 1 upwards; the "
      "first draw whose circles keep start and goal 3 clear, come closer than 1.5 to the "
      "straight start-goal segment (so the problem is not trivial) and leave a path keeping 1.5 "
      "is kept. Radii are our choice: the paper shows the maps only as figures.\n\n");

  for (const WorldRun& w : worlds) {
    absl::StrAppend(&out, "## Table 2 (", w.spec.name, "): aem-bso with three interpolations\n\n");
    std::vector<std::string> header = {"interpolation"};
    for (const std::string& h : OurHeader()) header.push_back(h);
    for (const char* h : {"paper shortest", "paper mean", "paper s/run"}) header.push_back(h);
    MarkdownTable table(header);
    for (const std::string& interpolation :
         {std::string("linear"), std::string("nearest"), std::string("spline")}) {
      std::vector<std::string> row = {interpolation};
      for (std::string& c : OurCells(w.cells.at({"aem-bso", interpolation}), w.optimum)) {
        row.push_back(std::move(c));
      }
      const std::optional<PaperCell> paper = PaperTable2(w.spec.name, interpolation);
      row.push_back(PaperNumber(paper, &PaperCell::shortest));
      row.push_back(PaperNumber(paper, &PaperCell::mean));
      row.push_back(PaperNumber(paper, &PaperCell::seconds));
      table.AddRow(std::move(row));
    }
    absl::StrAppend(&out, table.ToString(), "\n");
  }

  std::vector<std::string> environments;
  for (const WorldRun& w : worlds) environments.push_back(w.spec.name);
  const aem_bso::CellOf cell_of = [&worlds](const std::string& environment,
                                            const std::string& planner,
                                            const std::string& interpolation) -> const CellStats& {
    for (const WorldRun& w : worlds) {
      if (w.spec.name == environment) return w.cells.at({planner, interpolation});
    }
    return worlds.front().cells.at({planner, interpolation});
  };
  std::string interpolations, convergence;
  absl::StrAppend(&out, aem_bso::InterpolationTestsSection(environments, cell_of, &interpolations));
  for (const WorldRun& w : worlds) {
    absl::StrAppend(&out, "## Table 3 (", w.spec.name, "): the planners with the spline\n\n");
    std::vector<std::string> header = {"planner"};
    for (const std::string& h : OurHeader()) header.push_back(h);
    for (const char* h : {"paper shortest", "paper mean", "paper std", "paper s/run"}) {
      header.push_back(h);
    }
    MarkdownTable table(header);
    for (const std::string& planner : Planners()) {
      std::vector<std::string> row = {planner};
      for (std::string& c : OurCells(w.cells.at({planner, "spline"}), w.optimum)) {
        row.push_back(std::move(c));
      }
      const std::optional<PaperCell> paper = PaperTable3(w.spec.name, planner);
      row.push_back(PaperNumber(paper, &PaperCell::shortest));
      row.push_back(PaperNumber(paper, &PaperCell::mean));
      row.push_back(PaperNumber(paper, &PaperCell::std_dev));
      row.push_back(PaperNumber(paper, &PaperCell::seconds));
      table.AddRow(std::move(row));
    }
    absl::StrAppend(&out, table.ToString(), "\n");
  }

  absl::StrAppend(&out, aem_bso::ConvergenceSection(environments, Planners(), iterations, cell_of,
                                                    &convergence));
  absl::StrAppend(&out, "## The other combinations (not in the paper)\n\n");
  std::vector<std::string> header = {"environment", "planner", "interpolation"};
  for (const std::string& h : OurHeader()) header.push_back(h);
  MarkdownTable others(header, 3);
  for (const WorldRun& w : worlds) {
    for (const std::string& planner : Planners()) {
      if (planner == "aem-bso") continue;
      for (const std::string& interpolation : Interpolations()) {
        if (interpolation == "spline") continue;
        std::vector<std::string> row = {w.spec.name, planner, interpolation};
        for (std::string& c : OurCells(w.cells.at({planner, interpolation}), w.optimum)) {
          row.push_back(std::move(c));
        }
        others.AddRow(std::move(row));
      }
    }
  }
  absl::StrAppend(&out, others.ToString(), "\n");
  std::string significant, unstated, equal_budget, replicated;
  absl::StrAppend(&out, SignificanceSection(worlds, &significant));
  absl::StrAppend(&out, aem_bso::ReplicatedSection(replication.environments, Planners(), "aem-bso",
                                                   replication.runs, options.seed, &replicated));
  std::vector<aem_bso::VariantRuns> variant_runs;
  for (const WorldRun& w : worlds) variant_runs.push_back(w.variants);
  const aem_bso::OurCell ours = [&cell_of](const std::string& environment,
                                           const std::string& planner) -> const CellStats& {
    return cell_of(environment, planner, "spline");
  };
  const aem_bso::PaperStdDev paper_std = [](const std::string& environment,
                                            const std::string& planner) {
    const std::optional<PaperCell> cell = PaperTable3(environment, planner);
    return cell.has_value() ? cell->std_dev : std::nullopt;
  };
  absl::StrAppend(&out, aem_bso::UnstatedSettingsSection(variant_runs, ours, paper_std, &unstated));
  absl::StrAppend(&out, aem_bso::EqualBudgetSection(variant_runs, ours, iterations, &equal_budget));
  const size_t drawn =
      replication.environments.empty() ? 0 : replication.environments[0].worlds.size();
  replicated = absl::StrCat("With every environment drawn ", drawn, " times (*Table 3 on ", drawn,
                            " worlds per environment* above), the differences from aem-bso "
                            "that the tests support are: ",
                            replicated);
  const aem_bso::DiscussionTexts texts{significant,
                                       replicated,
                                       unstated,
                                       equal_budget,
                                       interpolations,
                                       convergence,
                                       aem_bso::WaypointCountSentence(variant_runs, ours)};
  absl::StrAppend(&out, aem_bso::Discussion(worlds, iterations, texts));
  return out;
}

}  // namespace

absl::StatusOr<std::string> RunAemBsoWorlds(const ExperimentOptions& options) {
  const int runs = options.quick ? kQuickRuns : (options.runs > 0 ? options.runs : kDefaultRuns);
  const int iterations = options.quick ? kQuickIterations : kIterations;
  std::vector<WorldRun> worlds;
  for (const AemBsoWorldSpec& spec : AemBsoWorldSpecs()) {
    absl::StatusOr<WorldRun> world = RunWorld(spec, options, runs, iterations);
    if (!world.ok()) return world.status();
    worlds.push_back(*std::move(world));
  }
  Replication replication;
  replication.runs = options.quick ? kQuickRuns : kReplicatedRuns;
  const int replicated_worlds = options.quick ? kQuickReplicatedWorlds : kReplicatedWorlds;
  for (const AemBsoWorldSpec& spec : AemBsoWorldSpecs()) {
    absl::StatusOr<aem_bso::ReplicatedEnvironment> environment = aem_bso::RunReplicatedEnvironment(
        spec, Planners(), options, replicated_worlds, replication.runs, iterations);
    if (!environment.ok()) return environment.status();
    replication.environments.push_back(*std::move(environment));
  }
  return Report(worlds, replication, options, runs, iterations);
}

absl::Status GenerateAemBsoWorlds(const std::string& dir) {
  for (const AemBsoWorldSpec& spec : AemBsoWorldSpecs()) {
    absl::StatusOr<ShapeWorld> world = aem_bso::MakeAemBsoWorld(spec);
    if (!world.ok()) return world.status();
    const std::string path = (std::filesystem::path(dir) / spec.file).string();
    std::ofstream out(path, std::ios::binary);
    out << FormatShapesJson(*world, absl::StrCat("aem-bso-worlds ", spec.name));
    if (!out) return absl::InternalError(absl::StrCat("cannot write ", path));
  }
  return absl::OkStatus();
}

}  // namespace swarmplan::bench
