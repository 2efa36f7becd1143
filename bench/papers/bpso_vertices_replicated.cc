#include "bench/papers/bpso_vertices_replicated.h"

#include <memory>
#include <optional>
#include <utility>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/bpso_vertices_paper.h"
#include "bench/papers/bpso_vertices_worlds.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/parallel_jobs.h"
#include "bench/significance.h"
#include "bench/statistics.h"
#include "core/map/map.h"

namespace swarmplan::bench::bpso {
namespace {

// One pair of configurations over a set of worlds, lengths over each world's optimum.
struct PairTests {
  std::vector<double> reference_ratios, other_ratios;          // every found run
  std::vector<double> reference_medians, other_medians;        // per world where both found
  std::vector<double> reference_iterations, other_iterations;  // every found run
  SuccessCount reference_found, other_found;
  std::optional<double> pooled_p, across_p, iteration_p, found_p;
  int other_lower_worlds = 0;
};

void Pool(const Runs& runs, double optimum, std::vector<double>* ratios,
          std::vector<double>* iterations, SuccessCount* found) {
  for (double r : DividedBy(runs.lengths, optimum)) ratios->push_back(r);
  iterations->insert(iterations->end(), runs.best_iterations.begin(), runs.best_iterations.end());
  found->successes += runs.found();
  found->runs += runs.count;
}

PairTests TestPair(const std::vector<const ReplicatedWorldRuns*>& worlds,
                   const ReplicatedPair& pair) {
  PairTests out;
  for (const ReplicatedWorldRuns* world : worlds) {
    const Runs& reference = world->configs[pair.reference];
    const Runs& other = world->configs[pair.other];
    Pool(reference, world->optimum, &out.reference_ratios, &out.reference_iterations,
         &out.reference_found);
    Pool(other, world->optimum, &out.other_ratios, &out.other_iterations, &out.other_found);
    const std::optional<double> reference_median =
        Median(DividedBy(reference.lengths, world->optimum));
    const std::optional<double> other_median = Median(DividedBy(other.lengths, world->optimum));
    if (reference_median && other_median) {
      out.reference_medians.push_back(*reference_median);
      out.other_medians.push_back(*other_median);
      if (*other_median < *reference_median) ++out.other_lower_worlds;
    }
  }
  out.pooled_p = RankSumP(out.other_ratios, out.reference_ratios);
  out.across_p = SignedRankP(out.other_medians, out.reference_medians);
  out.iteration_p = RankSumP(out.other_iterations, out.reference_iterations);
  out.found_p = SuccessP(out.other_found, out.reference_found);
  return out;
}

std::vector<const ReplicatedWorldRuns*> WorldsOf(const ReplicatedVertexCount& count) {
  std::vector<const ReplicatedWorldRuns*> out;
  for (const ReplicatedWorldRuns& world : count.worlds) out.push_back(&world);
  return out;
}

std::vector<const ReplicatedWorldRuns*> AllWorlds(
    const std::vector<ReplicatedVertexCount>& counts) {
  std::vector<const ReplicatedWorldRuns*> out;
  for (const ReplicatedVertexCount& count : counts) {
    for (const ReplicatedWorldRuns& world : count.worlds) out.push_back(&world);
  }
  return out;
}

std::string PerWorldTable(const std::vector<ReplicatedVertexCount>& counts) {
  std::vector<std::string> header = {"D", "world", "seed", "optimum (VG)"};
  for (const ReplicatedConfig& config : ReplicatedConfigs()) header.push_back(config.label);
  MarkdownTable table(header, 2);
  for (const ReplicatedVertexCount& count : counts) {
    for (const ReplicatedWorldRuns& world : count.worlds) {
      std::vector<std::string> row = {absl::StrCat(count.vertices),
                                      world.index == 0 ? "0 (shipped)" : absl::StrCat(world.index),
                                      absl::StrCat(world.seed), NumberCell(world.optimum)};
      for (const Runs& runs : world.configs) {
        row.push_back(absl::StrCat(runs.found(), "/", runs.count, " · ",
                                   NumberCell(Median(DividedBy(runs.lengths, world.optimum)))));
      }
      table.AddRow(std::move(row));
    }
  }
  return table.ToString();
}

void AddPooledRow(const std::string& vertices, const ReplicatedPair& pair, const PairTests& tests,
                  MarkdownTable* table) {
  const std::vector<ReplicatedConfig>& configs = ReplicatedConfigs();
  table->AddRow({vertices,
                 absl::StrCat(configs[pair.other].label, " vs ", configs[pair.reference].label),
                 MedianWithInterval(tests.reference_ratios), MedianWithInterval(tests.other_ratios),
                 PValueCell(tests.pooled_p),
                 absl::StrCat(tests.reference_found.successes, "/", tests.reference_found.runs,
                              " vs ", tests.other_found.successes, "/", tests.other_found.runs),
                 PValueCell(tests.found_p),
                 absl::StrCat(NumberCell(Median(tests.reference_iterations), 3), " vs ",
                              NumberCell(Median(tests.other_iterations), 3)),
                 PValueCell(tests.iteration_p),
                 absl::StrCat(tests.other_lower_worlds, "/", tests.other_medians.size()),
                 PValueCell(tests.across_p)});
}

std::string PooledTable(const std::vector<ReplicatedVertexCount>& counts) {
  MarkdownTable table(
      {"D", "comparison (other vs reference)", "reference: median length / opt [95% CI]",
       "other: median length / opt [95% CI]", "rank-sum p", "found", "Fisher p",
       "median iteration of final best", "rank-sum p (iteration)", "other's world median lower in",
       "signed-rank p (world medians)"},
      2);
  for (const ReplicatedPair& pair : ReplicatedPairs()) {
    for (const ReplicatedVertexCount& count : counts) {
      AddPooledRow(absl::StrCat(count.vertices), pair, TestPair(WorldsOf(count), pair), &table);
    }
    AddPooledRow("all", pair, TestPair(AllWorlds(counts), pair), &table);
  }
  return table.ToString();
}

// "lower on D = 16 (p = 0.003), D = 24 (p = 0.01)" for the significant ones.
std::string PerCountDifferences(const std::vector<ReplicatedVertexCount>& counts,
                                const ReplicatedPair& pair, bool across) {
  std::string out;
  for (const ReplicatedVertexCount& count : counts) {
    const PairTests tests = TestPair(WorldsOf(count), pair);
    AppendListItem(
        &out, across
                  ? ValueDifference(absl::StrCat("D = ", count.vertices), "world median",
                                    tests.reference_medians, tests.other_medians, tests.across_p)
                  : ValueDifference(absl::StrCat("D = ", count.vertices), "pooled length / optimum",
                                    tests.reference_ratios, tests.other_ratios, tests.pooled_p));
  }
  return out.empty() ? "none" : out;
}

std::string PText(std::optional<double> p) {
  return p ? FormatPValue(*p, /*mark_significant=*/false) : "no test";
}

std::string Verdict(const PairTests& tests) {
  const bool significant = tests.across_p && *tests.across_p < kSignificanceLevel;
  if (!significant) {
    return absl::StrFormat(
        "not supported: the paired test across worlds finds no difference at p < %g",
        kSignificanceLevel);
  }
  const bool lower =
      Median(tests.other_medians).value_or(0.0) < Median(tests.reference_medians).value_or(0.0);
  return lower ? "supported: lower world medians across worlds"
               : "contradicted: higher world medians across worlds";
}

}  // namespace

uint64_t ReplicatedBpsoWorldSeed(int vertices, int index) {
  return ReplicatedWorldSeed(ShippedWorldSeed(vertices), index);
}

absl::StatusOr<ShapeWorld> DrawReplicatedBpsoWorld(int vertices, int index) {
  return GenerateBpsoVerticesWorld(vertices / 4, ReplicatedBpsoWorldSeed(vertices, index));
}

const std::vector<ReplicatedConfig>& ReplicatedConfigs() {
  static const auto* configs = new std::vector<ReplicatedConfig>{
      {"N = 1D", 1.0, kPaperMutation},
      {"N = 2D", 2.0, kPaperMutation},
      {"N = 1.5D, mutation 0.1 (the paper's)", kPaperSwarmFactor, kPaperMutation},
      {"N = 1.5D, no mutation", kPaperSwarmFactor, 0.0},
  };
  return *configs;
}

const std::vector<ReplicatedPair>& ReplicatedPairs() {
  static const auto* pairs = new std::vector<ReplicatedPair>{
      {0, 1, "with the size of the swarm increases the average fitness value decreases"},
      {3, 2, "with the mutation operation ... the average fitness value also decreases"},
  };
  return *pairs;
}

absl::StatusOr<std::vector<ReplicatedVertexCount>> RunReplicatedBpsoWorlds(
    const ExperimentOptions& options, int worlds, int runs, int iterations) {
  std::vector<ReplicatedVertexCount> counts;
  for (int vertices : kVertexCounts) {
    ReplicatedVertexCount& count = counts.emplace_back();
    count.vertices = vertices;
    count.worlds.resize(worlds);
  }
  ProgressLog log(options.log);
  const int jobs = static_cast<int>(counts.size()) * worlds;
  absl::Status status = RunJobs(jobs, options.jobs, [&](int job) -> absl::Status {
    ReplicatedVertexCount& count = counts[job / worlds];
    ReplicatedWorldRuns& world = count.worlds[job % worlds];
    world.index = job % worlds;
    world.seed = ReplicatedBpsoWorldSeed(count.vertices, world.index);
    absl::StatusOr<ShapeWorld> drawn = DrawReplicatedBpsoWorld(count.vertices, world.index);
    if (!drawn.ok()) return drawn.status();
    const std::string name = absl::StrFormat("D = %d, world %d (seed %d)", count.vertices,
                                             world.index, static_cast<int64_t>(world.seed));
    absl::StatusOr<World> made =
        MakeWorld(std::make_shared<const Map>(Map(*std::move(drawn))), count.vertices, name);
    if (!made.ok()) return made.status();
    world.optimum = made->optimum;
    for (const ReplicatedConfig& config : ReplicatedConfigs()) {
      absl::StatusOr<Runs> result =
          RunMany(BpsoSpec(iterations, config.swarm_factor, config.mutation, true), *made, runs,
                  options.seed, config.label, nullptr);
      if (!result.ok()) return result.status();
      world.configs.push_back(*std::move(result));
    }
    log.Line(absl::StrCat("bpso-vertices: replicated ", name, " done"));
    return absl::OkStatus();
  });
  if (!status.ok()) return status;
  return counts;
}

std::string ReplicatedBpsoSection(const std::vector<ReplicatedVertexCount>& counts, int runs,
                                  uint64_t first_seed) {
  const int worlds = counts.empty() ? 0 : static_cast<int>(counts.front().worlds.size());
  std::string out = absl::StrFormat("## Table 1 and Fig. 5 on %d worlds per D\n\n", worlds);
  absl::StrAppend(
      &out,
      absl::StrFormat(
          "The paper's worlds are unpublished, so one drawn world could favour one "
          "configuration. Here each D has %d worlds drawn in memory by the same generator (world "
          "0 is the shipped one; world r draws from the shipped world's seed + %d r), and each "
          "configuration runs %d times (seeds %d..%d) on each. Lengths are divided by each "
          "world's visibility-graph optimum so that worlds can be pooled. *Per world*: found "
          "runs · median length / optimum.\n\n",
          worlds, kWorldSeedStride, runs, first_seed, first_seed + runs - 1),
      PerWorldTable(counts), "\n");
  absl::StrAppend(
      &out,
      "*Pooled* over every run of the worlds of one D (and of all D), the other configuration "
      "against the reference: length / optimum of the found runs and the iteration of the final "
      "best by the rank-sum test, found runs by Fisher's exact test, medians with bootstrap 95 % "
      "intervals. *Across worlds*: the signed-rank test on the per-world medians of length / "
      "optimum, paired by world: whether a difference holds from world to world rather than in "
      "the pooled runs of a few worlds.\n\n",
      PooledTable(counts), "\n");
  return out;
}

std::string ReplicatedBpsoSummary(const std::vector<ReplicatedVertexCount>& counts) {
  const std::vector<ReplicatedConfig>& configs = ReplicatedConfigs();
  const int worlds = counts.empty() ? 0 : static_cast<int>(counts.front().worlds.size());
  std::string out;
  for (const ReplicatedPair& pair : ReplicatedPairs()) {
    const PairTests all = TestPair(AllWorlds(counts), pair);
    absl::StrAppend(
        &out,
        absl::StrFormat(
            "- *%s against %s on %d worlds per D* (the paper's claim: \"%s\"). Pooled per D, "
            "differences of %s the tests support: %s. Paired across the worlds of one D: %s. "
            "Over all %d worlds: pooled %s; across worlds %s, %s in %d of %d worlds. The claim "
            "is %s.\n",
            configs[pair.other].label, configs[pair.reference].label, worlds, pair.claim,
            configs[pair.other].label, PerCountDifferences(counts, pair, false),
            PerCountDifferences(counts, pair, true), static_cast<int>(all.other_medians.size()),
            PText(all.pooled_p), PText(all.across_p), "its world median lower",
            all.other_lower_worlds, static_cast<int>(all.other_medians.size()), Verdict(all)));
  }
  return out;
}

}  // namespace swarmplan::bench::bpso
