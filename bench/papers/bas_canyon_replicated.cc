#include "bench/papers/bas_canyon_replicated.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/parallel_jobs.h"
#include "bench/statistics.h"

namespace swarmplan::bench::bas {
namespace {

RowSet DividedSet(const RowSet& set, double optimum) {
  RowSet out = set;
  for (RowRuns& runs : out.runs) runs.fitness = DividedBy(runs.fitness, optimum);
  return out;
}

// The rows' runs of every world together (fitness over each world's optimum).
RowSet Pooled(const std::vector<ReplicatedWorld>& worlds) {
  RowSet out;
  if (worlds.empty()) return out;
  out.rows = worlds.front().ratios.rows;
  out.runs.resize(out.rows.size());
  for (const ReplicatedWorld& world : worlds) {
    for (size_t r = 0; r < out.rows.size(); ++r) {
      const RowRuns& from = world.ratios.runs[r];
      RowRuns& to = out.runs[r];
      to.runs += from.runs;
      to.fitness.insert(to.fitness.end(), from.fitness.begin(), from.fitness.end());
      to.improved += from.improved;
      to.right_branch += from.right_branch;
    }
  }
  return out;
}

std::string CountCell(const SuccessCount& count) {
  return absl::StrCat(count.successes, "/", count.runs);
}

}  // namespace

absl::StatusOr<std::vector<ReplicatedWorld>> RunReplicatedCanyons(const std::vector<Row>& rows,
                                                                  const ExperimentOptions& options,
                                                                  int worlds, int runs,
                                                                  double lattice_vertical_step) {
  std::vector<CanyonWorld> canyons(worlds);
  if (absl::Status s = RunJobs(worlds, options.jobs,
                               [&](int w) -> absl::Status {
                                 absl::StatusOr<CanyonWorld> canyon =
                                     DrawCanyonWorld(w, lattice_vertical_step);
                                 if (!canyon.ok()) return canyon.status();
                                 canyons[w] = std::move(*canyon);
                                 return absl::OkStatus();
                               });
      !s.ok()) {
    return s;
  }
  std::vector<ReplicatedWorld> out;
  for (const CanyonWorld& canyon : canyons) {
    absl::StatusOr<RowSet> set = RunRows(rows, canyon, options, runs);
    if (!set.ok()) return set.status();
    ReplicatedWorld world;
    world.index = canyon.index;
    world.seed = canyon.seed;
    world.optimum = canyon.lattice.cost;
    world.ratios = DividedSet(*set, world.optimum);
    world.set = std::move(*set);
    out.push_back(std::move(world));
  }
  return out;
}

std::vector<ReplicatedPairTest> TestReplicatedPairs(const std::vector<ReplicatedWorld>& worlds,
                                                    const std::vector<ClaimedPair>& pairs) {
  const RowSet pooled = Pooled(worlds);
  std::vector<ReplicatedPairTest> out;
  for (const ClaimedPair& pair : pairs) {
    const RowRuns* reference = pooled.Find(pair.reference);
    const RowRuns* other = pooled.Find(pair.other);
    if (reference == nullptr || other == nullptr) continue;
    ReplicatedPairTest test;
    test.pair = pair;
    test.pooled = CompareRanks(reference->fitness, other->fitness);
    test.reference_found = reference->found();
    test.other_found = other->found();
    test.pooled_found_p = SuccessP(test.reference_found, test.other_found);
    std::vector<double> reference_medians, other_medians;
    for (const ReplicatedWorld& world : worlds) {
      const std::optional<double> a = Median(world.ratios.Find(pair.reference)->fitness);
      const std::optional<double> b = Median(world.ratios.Find(pair.other)->fitness);
      if (!a || !b) continue;
      reference_medians.push_back(*a);
      other_medians.push_back(*b);
      ++test.worlds;
      if (*b < *a) ++test.worlds_other_lower;
    }
    test.signed_rank_p = SignedRankP(reference_medians, other_medians);
    out.push_back(test);
  }
  return out;
}

std::string ReplicatedSection(const std::vector<ReplicatedWorld>& worlds,
                              const std::vector<ReplicatedPairTest>& tests) {
  if (worlds.empty()) return "";
  const std::vector<Row>& rows = worlds.front().set.rows;
  std::vector<std::string> header = {"world", "seed", "lattice optimum"};
  for (const Row& row : rows) header.push_back(row.label);
  MarkdownTable per_world(header);
  for (const ReplicatedWorld& world : worlds) {
    std::vector<std::string> cells = {absl::StrCat(world.index), absl::StrCat(world.seed),
                                      NumberCell(world.optimum)};
    for (const RowRuns& runs : world.ratios.runs) cells.push_back(NumberCell(Median(runs.fitness)));
    per_world.AddRow(cells);
  }
  const RowSet pooled = Pooled(worlds);
  MarkdownTable pooled_table({"planner", "found", "improved on first path",
                              "median fitness / optimum [95 % CI]", "deep branch"});
  for (size_t r = 0; r < pooled.rows.size(); ++r) {
    const RowRuns& runs = pooled.runs[r];
    pooled_table.AddRow({pooled.rows[r].label, CountCell(runs.found()),
                         CountCell(runs.improved_count()), MedianWithInterval(runs.fitness),
                         absl::StrCat(runs.right_branch, "/", runs.fitness.size())});
  }
  MarkdownTable pairs({"reference", "other", "claim (other's fitness lower)", "pooled rank-sum p",
                       "pooled Fisher p (found)", "signed-rank p (world medians)",
                       "worlds where other is lower", "verdict"});
  for (const ReplicatedPairTest& test : tests) {
    pairs.AddRow({test.pair.reference, test.pair.other, test.pair.claim, PValueCell(test.pooled.p),
                  PValueCell(test.pooled_found_p), PValueCell(test.signed_rank_p),
                  absl::StrCat(test.worlds_other_lower, "/", test.worlds),
                  test.supported()      ? "supported"
                  : test.contradicted() ? "contradicted"
                                        : "not significant"});
  }
  return absl::StrCat("Median fitness / lattice optimum per world:\n\n", per_world.ToString(),
                      "\nPooled over the worlds:\n\n", pooled_table.ToString(),
                      "\nThe headline pairs (signed-rank on the per-world medians decides):\n\n",
                      pairs.ToString());
}

}  // namespace swarmplan::bench::bas
