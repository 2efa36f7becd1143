#include "bench/papers/aem_bso_worlds_replicated.h"

#include <algorithm>
#include <memory>
#include <optional>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"
#include "core/map/map.h"

namespace swarmplan::bench::aem_bso {
namespace {

// A per-world median length counts as within 1 % of the optimum up to this ratio.
constexpr double kNearOptimum = 1.01;

// What a planner's runs on every world of an environment gave, in units of each world's
// optimum.
struct Pooled {
  SuccessCount found;
  std::vector<double> length_ratios;         // found runs of every world
  std::vector<double> median_z_ratios;       // one per world: the median of its runs' z / optimum
  std::vector<double> median_length_ratios;  // one per world with a found run
};

Pooled Pool(const ReplicatedEnvironment& environment, const std::string& planner) {
  Pooled out;
  for (const ReplicatedWorld& world : environment.worlds) {
    const CellStats& cell = world.cells.at(planner);
    out.found.successes += cell.found();
    out.found.runs += cell.runs;
    for (double r : DividedBy(cell.lengths, world.optimum)) out.length_ratios.push_back(r);
    out.median_z_ratios.push_back(Median(DividedBy(cell.fitnesses, world.optimum)).value_or(0.0));
    if (const std::optional<double> m = Median(DividedBy(cell.lengths, world.optimum))) {
      out.median_length_ratios.push_back(*m);
    }
  }
  return out;
}

// Worlds in which `theirs` has the lower per-world median, e.g. "3/10".
std::string LowerIn(const std::vector<double>& theirs, const std::vector<double>& reference) {
  int lower = 0;
  for (size_t i = 0; i < theirs.size() && i < reference.size(); ++i) {
    if (theirs[i] < reference[i]) ++lower;
  }
  return absl::StrCat(lower, "/", theirs.size());
}

std::string WorldsTable(const std::vector<ReplicatedEnvironment>& environments,
                        const std::vector<std::string>& planners) {
  std::vector<std::string> header = {"environment", "world", "first seed", "optimum"};
  for (const std::string& planner : planners) header.push_back(planner);
  MarkdownTable table(header, 2);
  for (const ReplicatedEnvironment& environment : environments) {
    for (size_t i = 0; i < environment.worlds.size(); ++i) {
      const ReplicatedWorld& world = environment.worlds[i];
      std::vector<std::string> row = {environment.name, i == 0 ? "0 (shipped)" : absl::StrCat(i),
                                      absl::StrCat(world.spec.seed), NumberCell(world.optimum)};
      for (const std::string& planner : planners) {
        const CellStats& cell = world.cells.at(planner);
        row.push_back(absl::StrCat(cell.found(), "/", cell.runs, " · ",
                                   NumberCell(Median(DividedBy(cell.lengths, world.optimum)))));
      }
      table.AddRow(std::move(row));
    }
  }
  return table.ToString();
}

}  // namespace

AemBsoWorldSpec ReplicatedSpec(const AemBsoWorldSpec& spec, int index) {
  AemBsoWorldSpec out = spec;
  out.seed = ReplicatedWorldSeed(spec.seed, index);
  if (index > 0) out.file.clear();
  return out;
}

absl::StatusOr<ReplicatedEnvironment> RunReplicatedEnvironment(
    const AemBsoWorldSpec& spec, const std::vector<std::string>& planners,
    const ExperimentOptions& options, int worlds, int runs, int iterations) {
  ReplicatedEnvironment out;
  out.name = spec.name;
  for (int index = 0; index < worlds; ++index) {
    ReplicatedWorld world;
    world.spec = ReplicatedSpec(spec, index);
    absl::StatusOr<ShapeWorld> drawn = MakeAemBsoWorld(world.spec);
    if (!drawn.ok()) return drawn.status();
    const MapPtr map = std::make_shared<const Map>(Map(*std::move(drawn)));
    const std::string what = absl::StrCat(spec.name, " world ", index);
    absl::StatusOr<double> optimum = ExactOptimum(map, options.seed, what);
    if (!optimum.ok()) return optimum.status();
    world.optimum = *optimum;
    for (const std::string& planner : planners) {
      absl::StatusOr<CellStats> cell = RunCell(PaperPlan(planner, "spline", iterations), map,
                                               options, runs, absl::StrCat(what, " ", planner));
      if (!cell.ok()) return cell.status();
      world.cells[planner] = *std::move(cell);
    }
    out.worlds.push_back(std::move(world));
  }
  return out;
}

std::string ReplicatedSection(const std::vector<ReplicatedEnvironment>& environments,
                              const std::vector<std::string>& planners,
                              const std::string& reference, int runs, uint64_t first_seed,
                              std::string* summary) {
  const int worlds = environments.empty() ? 0 : static_cast<int>(environments[0].worlds.size());
  std::string out = absl::StrFormat("## Table 3 on %d worlds per environment\n\n", worlds);
  absl::StrAppend(
      &out,
      absl::StrFormat(
          "The paper's worlds are unpublished, so one drawn world could favour one planner. "
          "Here each environment is drawn %d times by the same generator (world 0 is the "
          "shipped one; world r starts its draw at the shipped world's seed + %d r), and every "
          "planner runs %d times (seeds %d..%d) with the spline on each. Lengths and fitness "
          "are divided by each world's exact optimum so that worlds can be pooled. *Per "
          "world*: found runs · median length / optimum.\n\n",
          worlds, kWorldSeedStride, runs, first_seed, first_seed + runs - 1));
  absl::StrAppend(&out, WorldsTable(environments, planners), "\n");
  absl::StrAppend(
      &out, "*Pooled* over every run of every world, each planner against ", reference,
      ": found runs by Fisher's exact test, length / optimum of the found runs by the rank-sum "
      "test, medians with bootstrap 95 % intervals. *Across worlds*: the signed-rank test on "
      "the per-world medians of z / optimum (penalty included, so it weighs failures too), "
      "paired by world: whether a difference holds from world to world rather than in the "
      "pooled runs of a few worlds. *lower in*: worlds where the planner's median z is below ",
      reference, "'s.\n\n");
  MarkdownTable table({"environment", "planner", "found", "Fisher", "median length / opt",
                       "rank-sum", "median of world medians z / opt", "lower in", "signed-rank"},
                      2);
  for (const ReplicatedEnvironment& environment : environments) {
    const Pooled base = Pool(environment, reference);
    std::string differences;
    for (const std::string& planner : planners) {
      const Pooled pooled = Pool(environment, planner);
      std::vector<std::string> row = {environment.name, planner,
                                      absl::StrCat(pooled.found.successes, "/", pooled.found.runs)};
      if (planner == reference) {
        for (std::string cell :
             {std::string(), MedianWithInterval(pooled.length_ratios), std::string(),
              NumberCell(Median(pooled.median_z_ratios)), std::string(), std::string()}) {
          row.push_back(std::move(cell));
        }
        table.AddRow(std::move(row));
        continue;
      }
      const std::optional<double> found_p = SuccessP(base.found, pooled.found);
      const std::optional<double> length_p = RankSumP(base.length_ratios, pooled.length_ratios);
      const std::optional<double> worlds_p =
          SignedRankP(base.median_z_ratios, pooled.median_z_ratios);
      for (std::string cell :
           {PValueCell(found_p), MedianWithInterval(pooled.length_ratios), PValueCell(length_p),
            NumberCell(Median(pooled.median_z_ratios)),
            LowerIn(pooled.median_z_ratios, base.median_z_ratios), PValueCell(worlds_p)}) {
        row.push_back(std::move(cell));
      }
      table.AddRow(std::move(row));
      AppendListItem(&differences, SuccessDifference(planner, base.found, pooled.found, found_p));
      AppendListItem(&differences, ValueDifference(planner, "pooled length", base.length_ratios,
                                                   pooled.length_ratios, length_p));
      AppendListItem(&differences, ValueDifference(planner, "z across worlds", base.median_z_ratios,
                                                   pooled.median_z_ratios, worlds_p));
    }
    AppendListItem(
        summary,
        absl::StrCat(
            environment.name, " (", reference, "'s median length / optimum per world ",
            NumberCell(Min(base.median_length_ratios)), "-",
            NumberCell(Max(base.median_length_ratios)), ", within 1 % of the optimum in ",
            std::count_if(base.median_length_ratios.begin(), base.median_length_ratios.end(),
                          [](double r) { return r <= kNearOptimum; }),
            " of ", base.median_length_ratios.size(), " worlds, the shipped world ",
            NumberCell(Median(DividedBy(environment.worlds.front().cells.at(reference).lengths,
                                        environment.worlds.front().optimum))),
            "): ", differences.empty() ? "none" : differences),
        "; ");
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  return out;
}

}  // namespace swarmplan::bench::aem_bso
