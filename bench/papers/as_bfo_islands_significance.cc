#include "bench/papers/as_bfo_islands_significance.h"

#include "absl/strings/str_cat.h"
#include "bench/papers/as_bfo_islands_extremes.h"
#include "bench/papers/as_bfo_islands_runs.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench::as_bfo_islands {

SuccessCount OptimalCount(const Outcome& outcome, double optimum) {
  return SuccessCount{OptimalRuns(outcome, optimum), outcome.runs};
}

MethodTests TestAgainst(const Outcome& reference, const Outcome& other, double optimum) {
  MethodTests tests;
  tests.length = CompareRanks(reference.lengths, other.lengths);
  const SuccessCount reference_optimal = OptimalCount(reference, optimum);
  const SuccessCount other_optimal = OptimalCount(other, optimum);
  tests.optimal_p = SuccessP(reference_optimal, other_optimal);
  tests.fewer_optimal = other_optimal.rate() < reference_optimal.rate();
  tests.ain = CompareRanks(reference.ains, other.ains);
  tests.time = CompareRanks(reference.millis, other.millis);
  tests.min_p = ExtremePermutationP(reference.lengths, other.lengths, Extreme::kMin);
  tests.max_p = ExtremePermutationP(reference.lengths, other.lengths, Extreme::kMax);
  return tests;
}

std::vector<size_t> TestedMethods() {
  std::vector<size_t> methods;
  for (size_t m = 0; m < Methods().size(); ++m) {
    if (m != kReferenceMethod && Methods()[m].paper_row >= 0) methods.push_back(m);
  }
  return methods;
}

std::string SizeName(int n) { return absl::StrCat("S", n / 5 - 1, " ", n, "×", n); }

std::string Table4TestsSection(const std::vector<std::vector<World>>& worlds,
                               const Table4& outcomes) {
  const std::string& reference = Methods()[kReferenceMethod].label;
  std::string text = absl::StrCat("## Table 4: tests against ", reference, "\n\n");
  absl::StrAppend(
      &text, "Each method against ", reference,
      " on the same world: the runs that reach A*'s optimum by Fisher's exact test; the found "
      "paths' lengths (over A*'s optimum) and AIN by the rank-sum test; the shortest and longest "
      "run (MinPL, MaxPL: single runs, so the paper's best values) by a two-sided permutation "
      "test of the difference of the minima and of the maxima (",
      kExtremePermutations,
      " random relabellings of the pooled runs, seeded; a difference counts only when it is "
      "larger than relabelling explains). Medians with bootstrap 95% intervals; * marks p < ",
      kSignificanceLevel, ". Run times are tested in section \"Run times\".\n\n");
  MarkdownTable table({"environment", "size", "method", "optimal runs", "Fisher",
                       "median length / A* [95% CI]", "rank-sum", "median AIN [95% CI]", "rank-sum",
                       "MinPL / MaxPL", "permutation min", "permutation max"},
                      3);
  for (size_t e = 0; e < worlds.size(); ++e) {
    for (size_t s = 0; s < worlds[e].size(); ++s) {
      const World& world = worlds[e][s];
      const Outcome& base = outcomes[e][kReferenceMethod][s];
      auto medians = [&](const Outcome& o) {
        return std::vector<std::string>{
            MedianWithInterval(DividedBy(o.lengths, world.optimum)), MedianWithInterval(o.ains, 3),
            absl::StrCat(NumberCell(Min(o.lengths)), " / ", NumberCell(Max(o.lengths)))};
      };
      auto optimal = [&](const Outcome& o) {
        const SuccessCount count = OptimalCount(o, world.optimum);
        return absl::StrCat(count.successes, "/", count.runs);
      };
      const std::vector<std::string> base_medians = medians(base);
      table.AddRow({world.environment, SizeName(world.n), reference, optimal(base), "",
                    base_medians[0], "", base_medians[1], "", base_medians[2], "", ""});
      for (size_t m : TestedMethods()) {
        const Outcome& other = outcomes[e][m][s];
        const MethodTests tests = TestAgainst(base, other, world.optimum);
        const std::vector<std::string> other_medians = medians(other);
        table.AddRow({world.environment, SizeName(world.n), Methods()[m].label, optimal(other),
                      PValueCell(tests.optimal_p), other_medians[0], PValueCell(tests.length.p),
                      other_medians[1], PValueCell(tests.ain.p), other_medians[2],
                      PValueCell(tests.min_p), PValueCell(tests.max_p)});
      }
    }
  }
  absl::StrAppend(&text, table.ToString(), "\n");
  return text;
}

}  // namespace swarmplan::bench::as_bfo_islands
