#include "bench/papers/as_bfo_islands_replicated.h"

#include <optional>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/as_bfo_islands_runs.h"
#include "bench/papers/as_bfo_islands_significance.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

// A method's runs on every world of a cell, lengths over each world's optimum.
struct Pooled {
  SuccessCount found;
  SuccessCount optimal;
  std::vector<double> length_ratios;
};

Pooled Pool(const ReplicatedIslandCell& cell, size_t method) {
  Pooled out;
  for (const ReplicatedIslandRuns& runs : cell.worlds) {
    const Outcome& o = runs.outcomes[method];
    out.found.successes += static_cast<int>(o.lengths.size());
    out.found.runs += o.runs;
    out.optimal.successes += OptimalRuns(o, runs.world.optimum);
    out.optimal.runs += o.runs;
    for (double r : DividedBy(o.lengths, runs.world.optimum)) out.length_ratios.push_back(r);
  }
  return out;
}

// The per-world medians of length / optimum of `reference` and `other`, over the worlds where
// both found a path.
struct PairedMedians {
  std::vector<double> reference;
  std::vector<double> other;
};

PairedMedians PairMedians(const ReplicatedIslandCell& cell, size_t reference, size_t other) {
  PairedMedians out;
  for (const ReplicatedIslandRuns& runs : cell.worlds) {
    const std::optional<double> a =
        Median(DividedBy(runs.outcomes[reference].lengths, runs.world.optimum));
    const std::optional<double> b =
        Median(DividedBy(runs.outcomes[other].lengths, runs.world.optimum));
    if (!a || !b) continue;
    out.reference.push_back(*a);
    out.other.push_back(*b);
  }
  return out;
}

std::string CellName(const ReplicatedIslandCell& cell) {
  return absl::StrCat(cell.environment, " ", SizeName(cell.n));
}

std::string WorldsTable(const std::vector<ReplicatedIslandCell>& cells,
                        const std::vector<size_t>& methods) {
  std::vector<std::string> header = {"environment", "size",       "world",
                                     "first seed",  "seed drawn", "A* optimum"};
  for (size_t m : methods) header.push_back(Methods()[m].label);
  MarkdownTable table(header, 3);
  for (const ReplicatedIslandCell& cell : cells) {
    for (size_t w = 0; w < cell.worlds.size(); ++w) {
      const ReplicatedIslandRuns& runs = cell.worlds[w];
      std::vector<std::string> row = {cell.environment,
                                      SizeName(cell.n),
                                      w == 0 ? "0 (shipped)" : absl::StrCat(w),
                                      absl::StrCat(runs.first_seed),
                                      absl::StrCat(runs.seed_drawn),
                                      NumberCell(runs.world.optimum)};
      for (size_t i = 0; i < methods.size(); ++i) {
        const Outcome& o = runs.outcomes[i];
        const std::optional<double> median = Median(DividedBy(o.lengths, runs.world.optimum));
        row.push_back(absl::StrCat(o.lengths.size(), "/", o.runs, " · ",
                                   OptimalRuns(o, runs.world.optimum), " · ",
                                   median ? absl::StrFormat("%.3f", *median) : "–"));
      }
      table.AddRow(std::move(row));
    }
  }
  return table.ToString();
}

int CountLower(const std::vector<double>& a, const std::vector<double>& b) {
  int lower = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) lower += a[i] < b[i] ? 1 : 0;
  return lower;
}

}  // namespace

IslandEnvironmentSpec ReplicatedIslandSpec(const IslandEnvironmentSpec& shipped, int index) {
  IslandEnvironmentSpec spec = shipped;
  spec.seed = ReplicatedWorldSeed(shipped.seed, index);
  return spec;
}

absl::StatusOr<DrawnIslandWorld> DrawReplicatedIslands(const IslandEnvironmentSpec& shipped,
                                                       int index, const std::vector<int>& sizes) {
  const IslandEnvironmentSpec spec = ReplicatedIslandSpec(shipped, index);
  absl::StatusOr<IslandLayout> layout = AcceptedIslands(spec, AsBfoSizes());
  if (!layout.ok()) return layout.status();
  DrawnIslandWorld out;
  out.first_seed = spec.seed;
  out.seed_drawn = layout->seed;
  for (int n : sizes) {
    absl::StatusOr<OccupancyGrid> grid = RasteriseIslands(layout->discs, n, spec.obstacle_ratio);
    if (!grid.ok()) return grid.status();
    out.grids.push_back(*std::move(grid));
  }
  return out;
}

absl::StatusOr<std::vector<ReplicatedIslandCell>> RunReplicatedIslands(
    const std::vector<size_t>& methods, const std::vector<int>& sizes,
    const ExperimentOptions& options, int worlds, int runs, int max_iterations) {
  std::vector<ReplicatedIslandCell> cells;
  for (const IslandEnvironmentSpec& shipped : AsBfoEnvironments()) {
    const size_t first = cells.size();
    for (int n : sizes) cells.push_back({shipped.name, n, {}});
    for (int index = 0; index < worlds; ++index) {
      absl::StatusOr<DrawnIslandWorld> drawn = DrawReplicatedIslands(shipped, index, sizes);
      if (!drawn.ok()) return drawn.status();
      for (size_t s = 0; s < sizes.size(); ++s) {
        ReplicatedIslandRuns world_runs;
        world_runs.first_seed = drawn->first_seed;
        world_runs.seed_drawn = drawn->seed_drawn;
        absl::StatusOr<World> world =
            MakeWorld(shipped.name, std::move(drawn->grids[s]), options.seed);
        if (!world.ok()) return world.status();
        world_runs.world = *std::move(world);
        for (size_t m : methods) {
          PlanSpec spec{Methods()[m].algorithm, Methods()[m].params};
          spec.max_iterations = max_iterations;
          absl::StatusOr<Outcome> outcome = RunConfig(spec, world_runs.world, runs, options.seed);
          if (!outcome.ok()) return outcome.status();
          world_runs.outcomes.push_back(*std::move(outcome));
        }
        if (options.log != nullptr) {
          *options.log << "replicated " << shipped.name << " " << sizes[s] << "x" << sizes[s]
                       << " world " << index << "\n";
        }
        cells[first + s].worlds.push_back(std::move(world_runs));
      }
    }
  }
  return cells;
}

std::string ReplicatedIslandsSection(const std::vector<ReplicatedIslandCell>& cells,
                                     const std::vector<size_t>& methods, int runs,
                                     uint64_t first_seed, std::string* summary) {
  const int worlds = cells.empty() ? 0 : static_cast<int>(cells.front().worlds.size());
  const std::string& reference = Methods()[methods.front()].label;
  std::string out = absl::StrFormat("## Table 4 on %d worlds per environment\n\n", worlds);
  absl::StrAppend(
      &out,
      absl::StrFormat(
          "The paper's maps are unpublished, so one drawn world could favour one method. Here "
          "each environment is drawn %d times by the same generator, in memory (world 0 is the "
          "shipped one; world r starts its draw at the shipped seed + %d r, \"first seed\"; "
          "\"seed drawn\" is the first accepted), and every method runs %d times (seeds %d..%d) "
          "at each size. *Per world*: found runs · runs at A*'s optimum · median length / "
          "optimum.\n\n",
          worlds, kWorldSeedStride, runs, first_seed, first_seed + runs - 1));
  absl::StrAppend(&out, WorldsTable(cells, methods), "\n");
  absl::StrAppend(
      &out, "*Pooled* over every run of every world, each method against ", reference,
      ": found and optimal runs by Fisher's exact test, length / optimum of the found runs by "
      "the rank-sum test, medians with bootstrap 95% intervals. *Across worlds*: the signed-rank "
      "test on the per-world medians of length / optimum, paired by world (over the worlds where "
      "both found a path): whether a difference holds from world to world. *lower / higher in*: "
      "worlds where the method's median is below / above ",
      reference, "'s.\n\n");
  MarkdownTable table({"environment", "size", "method", "found", "Fisher", "optimal runs", "Fisher",
                       "median length / opt [95% CI]", "rank-sum", "median of world medians",
                       "lower / higher in", "signed-rank"},
                      3);
  for (const ReplicatedIslandCell& cell : cells) {
    const Pooled base = Pool(cell, 0);
    std::string differences;
    for (size_t i = 0; i < methods.size(); ++i) {
      const Pooled pooled = Pool(cell, i);
      std::vector<std::string> row = {
          cell.environment,
          SizeName(cell.n),
          Methods()[methods[i]].label,
          absl::StrCat(pooled.found.successes, "/", pooled.found.runs),
          "",
          absl::StrCat(pooled.optimal.successes, "/", pooled.optimal.runs),
          "",
          MedianWithInterval(pooled.length_ratios)};
      if (i == 0) {
        std::vector<double> medians;
        for (const ReplicatedIslandRuns& r : cell.worlds) {
          if (auto m = Median(DividedBy(r.outcomes[0].lengths, r.world.optimum))) {
            medians.push_back(*m);
          }
        }
        row.insert(row.end(), {"", NumberCell(Median(medians)), "", ""});
        table.AddRow(std::move(row));
        continue;
      }
      const std::string& label = Methods()[methods[i]].label;
      const std::optional<double> found_p = SuccessP(base.found, pooled.found);
      const std::optional<double> optimal_p = SuccessP(base.optimal, pooled.optimal);
      const RankComparison length = CompareRanks(base.length_ratios, pooled.length_ratios);
      const PairedMedians paired = PairMedians(cell, 0, i);
      const std::optional<double> worlds_p = SignedRankP(paired.reference, paired.other);
      row[4] = PValueCell(found_p);
      row[6] = PValueCell(optimal_p);
      row.insert(row.end(), {PValueCell(length.p), NumberCell(Median(paired.other)),
                             absl::StrCat(CountLower(paired.other, paired.reference), " / ",
                                          CountLower(paired.reference, paired.other)),
                             PValueCell(worlds_p)});
      table.AddRow(std::move(row));
      AppendListItem(&differences, SuccessDifference(label, base.found, pooled.found, found_p));
      if (Significant(optimal_p)) {
        AppendListItem(&differences,
                       absl::StrCat(label, " at the optimum ",
                                    pooled.optimal.rate() < base.optimal.rate() ? "less" : "more",
                                    " often (", FormatPValue(*optimal_p, false), ")"));
      }
      if (Significant(length.p)) {
        AppendListItem(&differences, absl::StrCat(label, "'s pooled length / optimum ",
                                                  length.other_higher ? "higher" : "lower", " (",
                                                  FormatPValue(*length.p, false), ")"));
      }
      if (Significant(worlds_p)) {
        AppendListItem(
            &differences,
            absl::StrCat(label, "'s median higher in ", CountLower(paired.reference, paired.other),
                         " and lower in ", CountLower(paired.other, paired.reference), " of ",
                         paired.reference.size(), " worlds (signed-rank ",
                         FormatPValue(*worlds_p, false), ")"));
      }
    }
    if (!differences.empty()) {
      AppendListItem(summary, absl::StrCat(CellName(cell), ": ", differences), "; ");
    }
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  return out;
}

}  // namespace swarmplan::bench::as_bfo_islands
