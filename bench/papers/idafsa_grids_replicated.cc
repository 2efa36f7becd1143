#include "bench/papers/idafsa_grids_replicated.h"

#include <memory>
#include <optional>
#include <utility>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/comparison.h"
#include "bench/papers/idafsa_grids_significance.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"
#include "core/map/map.h"

namespace swarmplan::bench {
namespace {

// A configuration's runs on one world, lengths over the world's optimum.
ComparedRuns RunsOnWorld(const std::string& label, const ReplicatedIdafsaWorldRuns& world,
                         size_t config) {
  ComparedRuns runs = CompareRunsOf(label, world.configs[config]);
  runs.lengths = DividedBy(runs.lengths, world.optimum);
  return runs;
}

// A configuration's runs on all worlds of a grid size, lengths over each world's optimum.
ComparedRuns PooledRuns(const std::string& label, const ReplicatedIdafsaGrid& grid, size_t config) {
  ComparedRuns pooled{label, {}, {}, {}};
  for (const ReplicatedIdafsaWorldRuns& world : grid.worlds) {
    const ComparedRuns runs = RunsOnWorld(label, world, config);
    pooled.success.successes += runs.success.successes;
    pooled.success.runs += runs.success.runs;
    pooled.lengths.insert(pooled.lengths.end(), runs.lengths.begin(), runs.lengths.end());
    pooled.turning_points.insert(pooled.turning_points.end(), runs.turning_points.begin(),
                                 runs.turning_points.end());
  }
  return pooled;
}

// idafsa against one configuration across the worlds of a grid size.
struct AcrossWorlds {
  // Per-world medians of length / optimum, over the worlds where both have successful runs.
  std::vector<double> reference_medians, other_medians;
  std::vector<double> reference_rates, other_rates;       // per-world success rates, every world
  std::optional<double> length_p, success_p;              // signed-rank tests of the pairs
  int shorter_worlds = 0, longer_worlds = 0;              // single-world rank-sum p < 0.05
  int more_success_worlds = 0, fewer_success_worlds = 0;  // single-world Fisher p < 0.05
};

bool Significant(std::optional<double> p) { return p.has_value() && *p < kSignificanceLevel; }

int CountLower(const std::vector<double>& a, const std::vector<double>& b) {
  int n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a[i] < b[i] ? 1 : 0;
  return n;
}

AcrossWorlds CompareAcrossWorlds(const ReplicatedIdafsaGrid& grid, size_t reference, size_t other) {
  AcrossWorlds across;
  for (const ReplicatedIdafsaWorldRuns& world : grid.worlds) {
    const ComparedRuns ref = RunsOnWorld("reference", world, reference);
    const ComparedRuns oth = RunsOnWorld("other", world, other);
    across.reference_rates.push_back(ref.success.rate());
    across.other_rates.push_back(oth.success.rate());
    if (!ref.lengths.empty() && !oth.lengths.empty()) {
      across.reference_medians.push_back(*Median(ref.lengths));
      across.other_medians.push_back(*Median(oth.lengths));
    }
    const ComparisonTests tests = TestAgainst(ref, oth);
    if (Significant(tests.length_p)) {
      ++(*Median(ref.lengths) < *Median(oth.lengths) ? across.shorter_worlds
                                                     : across.longer_worlds);
    }
    if (Significant(tests.success_p)) {
      ++(ref.success.rate() > oth.success.rate() ? across.more_success_worlds
                                                 : across.fewer_success_worlds);
    }
  }
  across.length_p = SignedRankP(across.reference_medians, across.other_medians);
  across.success_p = SignedRankP(across.reference_rates, across.other_rates);
  return across;
}

std::string WorldCell(const ComparedRuns& runs) {
  const std::optional<double> median = Median(runs.lengths);
  return absl::StrCat(runs.success.successes, "/", runs.success.runs, " · ",
                      median ? absl::StrFormat("%.3f", *median) : std::string("–"));
}

std::string PerWorldTable(const ReplicatedIdafsaGrid& grid,
                          const std::vector<FishConfig>& configs) {
  std::vector<std::string> header = {"world",   "first seed",         "seed drawn",
                                     "blocked", "optimum (24 moves)", "Theta*"};
  for (const FishConfig& config : configs) header.push_back(config.label);
  MarkdownTable table(header);
  for (size_t w = 0; w < grid.worlds.size(); ++w) {
    const ReplicatedIdafsaWorldRuns& world = grid.worlds[w];
    std::vector<std::string> row = {absl::StrCat(w, w == 0 ? " (shipped)" : ""),
                                    absl::StrCat(world.spec.seed),
                                    absl::StrCat(world.seed_drawn),
                                    absl::StrCat(world.blocked),
                                    absl::StrFormat("%.4f", world.optimum),
                                    absl::StrFormat("%.4f", world.theta_star)};
    for (size_t c = 0; c < configs.size(); ++c) {
      row.push_back(WorldCell(RunsOnWorld(configs[c].label, world, c)));
    }
    table.AddRow(row);
  }
  return table.ToString();
}

std::string PairCell(int a, int b) { return absl::StrCat(a, " / ", b); }

std::string AcrossWorldsTable(const ReplicatedIdafsaGrid& grid,
                              const std::vector<FishConfig>& configs, size_t reference) {
  MarkdownTable table({"configuration", "worlds where both succeeded",
                       "idafsa's median lower / higher in", "signed-rank p (length / optimum)",
                       "idafsa's success rate higher / lower in", "signed-rank p (success rate)",
                       "single worlds: idafsa shorter / longer",
                       "single worlds: idafsa more / fewer successes"});
  for (size_t c = 0; c < configs.size(); ++c) {
    if (c == reference) continue;
    const AcrossWorlds across = CompareAcrossWorlds(grid, reference, c);
    table.AddRow({configs[c].label, absl::StrCat(across.reference_medians.size()),
                  PairCell(CountLower(across.reference_medians, across.other_medians),
                           CountLower(across.other_medians, across.reference_medians)),
                  PValueCell(across.length_p),
                  PairCell(CountLower(across.other_rates, across.reference_rates),
                           CountLower(across.reference_rates, across.other_rates)),
                  PValueCell(across.success_p),
                  PairCell(across.shorter_worlds, across.longer_worlds),
                  PairCell(across.more_success_worlds, across.fewer_success_worlds)});
  }
  return table.ToString();
}

// "shorter than dafsa in 3, less often successful than dafsa in 1" over the single-world tests;
// empty when no world shows a significant difference.
std::string SingleWorldCounts(const std::string& label, const AcrossWorlds& across) {
  std::string counts;
  const std::pair<int, const char*> parts[] = {
      {across.shorter_worlds, "shorter than"},
      {across.longer_worlds, "longer than"},
      {across.more_success_worlds, "more often successful than"},
      {across.fewer_success_worlds, "less often successful than"},
  };
  for (const auto& [n, what] : parts) {
    if (n > 0) AppendListItem(&counts, absl::StrCat(what, " ", label, " in ", n));
  }
  return counts;
}

// "1 of 10 runs on the shipped world, 84 of 90 on the others, Fisher's p = 2.5e-08".
std::string ShippedAgainstDrawn(const ReplicatedIdafsaGrid& grid, size_t config) {
  SuccessCount shipped, drawn;
  for (size_t w = 0; w < grid.worlds.size(); ++w) {
    const FishRunStats& stats = grid.worlds[w].configs[config];
    SuccessCount& count = w == 0 ? shipped : drawn;
    count.successes += stats.successes();
    count.runs += stats.runs;
  }
  const std::optional<double> p = SuccessP(shipped, drawn);
  return absl::StrFormat("%d of %d runs on the shipped world, %d of %d on the others, Fisher's %s",
                         shipped.successes, shipped.runs, drawn.successes, drawn.runs,
                         p ? FormatPValue(*p, /*mark_significant=*/false) : "no test");
}

std::string GridSummary(const ReplicatedIdafsaGrid& grid, const std::vector<FishConfig>& configs,
                        size_t reference, int runs) {
  const std::string& ref_label = configs[reference].label;
  const ComparedRuns pooled_ref = PooledRuns(ref_label, grid, reference);
  std::vector<ComparedRuns> pooled_others;
  std::string across_differences, single_worlds;
  for (size_t c = 0; c < configs.size(); ++c) {
    if (c == reference) continue;
    const std::string& label = configs[c].label;
    pooled_others.push_back(PooledRuns(label, grid, c));
    const AcrossWorlds across = CompareAcrossWorlds(grid, reference, c);
    AppendListItem(&across_differences,
                   ValueDifference(label, "median length / optimum", across.reference_medians,
                                   across.other_medians, across.length_p));
    AppendListItem(&across_differences,
                   ValueDifference(label, "success rate", across.reference_rates,
                                   across.other_rates, across.success_p));
    AppendListItem(&single_worlds, SingleWorldCounts(label, across), "; ");
  }
  std::string across_verdict;
  for (const ClaimTests& claim : AcrossWorldClaims(grid, configs, reference)) {
    AppendListItem(&across_verdict, ClaimVerdict(claim), " ");
  }
  const int worlds = static_cast<int>(grid.worlds.size());
  return absl::StrFormat(
      "- **%d worlds of %d x %d** (%d runs per configuration and world; %s succeeded in %s).\n"
      "  - Pooled runs, differences from %s the tests support: %s.\n"
      "  - Paired across worlds (signed-rank test on the per-world medians and success rates): "
      "%s.\n"
      "  - Single worlds (%d runs each, p < 0.05 within the world), of %d worlds: %s %s.\n"
      "  - The paper's headline on the pooled runs: %s\n"
      "  - The paper's headline across worlds: %s\n",
      worlds, grid.size, grid.size, runs, ref_label, ShippedAgainstDrawn(grid, reference),
      ref_label, SupportedDifferences(pooled_ref, pooled_others),
      across_differences.empty() ? "none" : across_differences, runs, worlds, ref_label,
      single_worlds.empty() ? "differs significantly from no configuration in any world"
                            : absl::StrCat("is significantly ", single_worlds),
      HeadlineVerdict(pooled_ref, pooled_others), across_verdict);
}

}  // namespace

std::vector<ClaimTests> PooledClaims(const ReplicatedIdafsaGrid& grid,
                                     const std::vector<FishConfig>& configs, size_t reference) {
  std::vector<ComparedRuns> others;
  for (size_t c = 0; c < configs.size(); ++c) {
    if (c != reference) others.push_back(PooledRuns(configs[c].label, grid, c));
  }
  return HeadlineClaims(PooledRuns(configs[reference].label, grid, reference), others);
}

std::vector<ClaimTests> AcrossWorldClaims(const ReplicatedIdafsaGrid& grid,
                                          const std::vector<FishConfig>& configs,
                                          size_t reference) {
  std::vector<ClaimTests> claims = {{"Shorter paths", "no world where both succeeded", {}},
                                    {"Higher success", "no worlds", {}}};
  for (size_t c = 0; c < configs.size(); ++c) {
    if (c == reference) continue;
    const AcrossWorlds across = CompareAcrossWorlds(grid, reference, c);
    claims[0].tests.push_back({configs[c].label, across.length_p,
                               Median(across.reference_medians).value_or(0.0) <
                                   Median(across.other_medians).value_or(0.0)});
    claims[1].tests.push_back(
        {configs[c].label, across.success_p,
         Mean(across.reference_rates).value_or(0.0) > Mean(across.other_rates).value_or(0.0)});
  }
  return claims;
}

IdafsaGridWorld ReplicatedIdafsaWorld(const IdafsaGridWorld& shipped, int index) {
  IdafsaGridWorld world = shipped;
  world.seed = ReplicatedWorldSeed(shipped.seed, index);
  if (index > 0) {
    world.file =
        absl::StrFormat("%dx%d world %d (drawn in memory)", shipped.size, shipped.size, index);
  }
  return world;
}

absl::StatusOr<ReplicatedIdafsaGrid> RunReplicatedIdafsaGrid(const IdafsaGridWorld& shipped,
                                                             const std::vector<FishConfig>& configs,
                                                             const ExperimentOptions& options,
                                                             int worlds, int runs,
                                                             int generations) {
  ReplicatedIdafsaGrid grid;
  grid.size = shipped.size;
  for (int r = 0; r < worlds; ++r) {
    ReplicatedIdafsaWorldRuns world;
    world.spec = ReplicatedIdafsaWorld(shipped, r);
    absl::StatusOr<DrawnIdafsaGrid> drawn = DrawIdafsaGrid(world.spec);
    if (!drawn.ok()) return drawn.status();
    world.seed_drawn = drawn->seed;
    const MapPtr map = std::make_shared<const Map>(Map(std::move(drawn->grid)));
    const OccupancyGrid& cells = *map->grid();
    world.blocked = static_cast<int>(cells.BlockedCount());
    const std::optional<double> optimum =
        MoveSetOptimum(cells, Neighbourhood::k24, IdafsaStart(world.spec), IdafsaGoal(world.spec));
    if (!optimum.has_value()) {
      return absl::InternalError(absl::StrCat(world.spec.file,
                                              ": no path of 24-neighbourhood "
                                              "moves on a connected grid"));
    }
    world.optimum = *optimum;
    absl::StatusOr<PlanResult> theta = RunReference("theta-star", world.spec, map);
    if (!theta.ok()) return theta.status();
    world.theta_star = theta->raw_metrics.length;
    for (const FishConfig& config : configs) {
      if (options.log) {
        *options.log << "idafsa-grids: " << world.spec.file << " " << config.label << "\n";
      }
      absl::StatusOr<FishRunStats> stats =
          RunFishConfig(config, world.spec, map, options, runs, generations);
      if (!stats.ok()) return stats.status();
      world.configs.push_back(*std::move(stats));
    }
    grid.worlds.push_back(std::move(world));
  }
  return grid;
}

std::string ReplicatedIdafsaSection(const std::vector<ReplicatedIdafsaGrid>& grids,
                                    const std::vector<FishConfig>& configs, size_t reference,
                                    int runs, std::string* summary) {
  std::string out = absl::StrFormat(
      "## Replication: drawn worlds per grid size (ours, not in the paper)\n\n"
      "One generated world says little about a planner: the tables above may reflect that "
      "world's layout. Here each grid size has %d worlds drawn by the same generator in memory "
      "(not shipped): world 0 is the shipped world, world r draws from seed (shipped seed) + "
      "r x %d on (\"first seed\"; \"seed drawn\" is the first that joins start and goal). Every "
      "configuration runs %d times on each world (seeds as above). Lengths are of the successful "
      "runs over the world's optimum (the shortest path of segment-checked 24-neighbourhood "
      "moves, the best a `dafsa` or `idafsa` path can be, so 1 is optimal); a cell of the "
      "per-world table gives successes / runs · median length / optimum. The pooled table holds "
      "the runs of all worlds, tested against %s (Fisher's exact test on success, rank-sum on "
      "length / optimum and turning points; medians with bootstrap 95%% intervals). The paired "
      "table asks whether a difference holds across worlds: the signed-rank test on the "
      "per-world medians (over the worlds where both succeeded) and on the per-world success "
      "rates, and how many single worlds show a significant difference on their own.\n\n",
      grids.empty() ? 0 : static_cast<int>(grids.front().worlds.size()), kWorldSeedStride, runs,
      configs[reference].label);
  for (const ReplicatedIdafsaGrid& grid : grids) {
    const ComparedRuns pooled_ref = PooledRuns(configs[reference].label, grid, reference);
    std::vector<ComparedRuns> pooled_others;
    for (size_t c = 0; c < configs.size(); ++c) {
      if (c != reference) pooled_others.push_back(PooledRuns(configs[c].label, grid, c));
    }
    absl::StrAppend(&out,
                    absl::StrFormat("### %d x %d: %d worlds\n\n", grid.size, grid.size,
                                    static_cast<int>(grid.worlds.size())),
                    "Per world:\n\n", PerWorldTable(grid, configs), "\nPooled over the worlds:\n\n",
                    ComparisonTable(pooled_ref, pooled_others, "median length / optimum [95% CI]"),
                    "\nPaired across worlds, ", configs[reference].label,
                    " against each configuration:\n\n", AcrossWorldsTable(grid, configs, reference),
                    "\n");
    absl::StrAppend(summary, GridSummary(grid, configs, reference, runs));
  }
  return out;
}

}  // namespace swarmplan::bench
