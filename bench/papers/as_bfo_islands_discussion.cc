#include "bench/papers/as_bfo_islands_discussion.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/as_bfo_islands_morris.h"
#include "bench/papers/as_bfo_islands_paper.h"
#include "bench/papers/as_bfo_islands_runs.h"
#include "bench/papers/as_bfo_islands_significance.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

namespace paper = as_bfo_paper;

// The paper's index (S1..S5 = 0..4) of an n x n size.
int PaperSize(int n) { return n / 5 - 2; }

std::string Short(const World& w) { return absl::StrCat(w.environment, " S", w.n / 5 - 1); }

// "a–b", or "a" when both print the same.
std::string Range(const std::vector<double>& values, int significant = 2,
                  const std::string& unit = "") {
  if (values.empty()) return "–";
  const std::string low = NumberCell(Min(values), significant);
  const std::string high = NumberCell(Max(values), significant);
  return low == high ? low + unit : absl::StrCat(low, "–", high, unit);
}

// "a–b" of run counts.
std::string CountRange(const std::vector<double>& counts) {
  if (counts.empty()) return "–";
  const int low = static_cast<int>(*Min(counts));
  const int high = static_cast<int>(*Max(counts));
  return low == high ? absl::StrCat(low) : absl::StrCat(low, "–", high);
}

std::string Percent(double fraction) { return absl::StrFormat("%.1f%%", 100.0 * fraction); }

std::string PText(std::optional<double> p) {
  return p ? FormatPValue(*p, /*mark_significant=*/false) : "no test";
}

// The first index of a method among Methods() with this algorithm, in the paper's rows or in
// the ablation (near-A* initial paths).
size_t MethodIndex(const std::string& algorithm, bool ablation) {
  for (size_t m = 0; m < Methods().size(); ++m) {
    if (Methods()[m].algorithm == algorithm && (Methods()[m].paper_row < 0) == ablation) return m;
  }
  return 0;
}

// "1.4, 8.7, 15 (S1 → S3: rises at every size)": a method's values over the sizes.
std::string Shape(const std::vector<double>& values, const std::vector<int>& sizes) {
  std::string list;
  for (double v : values) AppendListItem(&list, NumberCell(v, 2));
  if (values.size() < 2) return list;
  bool rising = true, falling = true;
  for (size_t i = 1; i < values.size(); ++i) {
    rising = rising && values[i] > values[i - 1];
    falling = falling && values[i] < values[i - 1];
  }
  const size_t peak = std::max_element(values.begin(), values.end()) - values.begin();
  std::string shape;
  if (rising) {
    shape = "rises at every size";
  } else if (falling) {
    shape = "falls at every size";
  } else {
    shape = absl::StrCat("highest at S", sizes[peak] / 5 - 1);
  }
  return absl::StrCat(list, " (S", sizes.front() / 5 - 1, " → S", sizes.back() / 5 - 1, ": ", shape,
                      ")");
}

// Where the tests found `other` differing from AS-BFO in one direction, e.g.
// "env2 S3 (p = 0.001), env2 S4 (p = 2e-05)"; empty when nowhere.
struct CellList {
  std::string cells;
  int count = 0;
  void Add(const World& w, std::optional<double> p) {
    AppendListItem(&cells, absl::StrCat(Short(w), " (", PText(p), ")"));
    ++count;
  }
  std::string Or(const std::string& none) const { return count == 0 ? none : cells; }
};

struct MethodFindings {
  CellList longer, shorter, fewer_optimal, more_optimal, more_iterations, fewer_iterations, slower,
      faster;
};

MethodFindings FindingsOf(const DiscussionInputs& in, size_t m) {
  MethodFindings f;
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    for (size_t s = 0; s < in.worlds[e].size(); ++s) {
      const World& w = in.worlds[e][s];
      const MethodTests t =
          TestAgainst(in.outcomes[e][kReferenceMethod][s], in.outcomes[e][m][s], w.optimum);
      if (Significant(t.length.p))
        (t.length.other_higher ? f.longer : f.shorter).Add(w, t.length.p);
      if (Significant(t.optimal_p)) {
        (t.fewer_optimal ? f.fewer_optimal : f.more_optimal).Add(w, t.optimal_p);
      }
      if (Significant(t.ain.p)) {
        (t.ain.other_higher ? f.more_iterations : f.fewer_iterations).Add(w, t.ain.p);
      }
      if (Significant(t.time.p)) (t.time.other_higher ? f.slower : f.faster).Add(w, t.time.p);
    }
  }
  return f;
}

int CellCount(const DiscussionInputs& in) {
  int cells = 0;
  for (const std::vector<World>& e : in.worlds) cells += static_cast<int>(e.size());
  return cells;
}

// A value of our Table 4 per cell, e.g. every cell's mean AIN of method m.
std::vector<double> PerCell(
    const DiscussionInputs& in, size_t m,
    const std::function<std::optional<double>(const Outcome&, const World&)>& value) {
  std::vector<double> out;
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    for (size_t s = 0; s < in.worlds[e].size(); ++s) {
      if (auto v = value(in.outcomes[e][m][s], in.worlds[e][s])) out.push_back(*v);
    }
  }
  return out;
}

std::optional<double> MeanAin(const Outcome& o, const World&) { return Mean(o.ains); }

std::string IterationsParagraph(const DiscussionInputs& in) {
  const size_t ablation = MethodIndex("as-bfo", true);
  std::vector<double> paper_ain;
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    for (const World& w : in.worlds[e]) paper_ain.push_back(paper::kAin[e][0][PaperSize(w.n)]);
  }
  std::vector<double> sweep_default, sweep_wandering;
  const SweepRow* highest = nullptr;
  for (const SweepRow& row : in.sweep_rows) {
    if (auto a = Mean(row.outcome.ains)) sweep_default.push_back(*a);
    if (auto a = Mean(row.wandering.ains)) {
      sweep_wandering.push_back(*a);
      if (highest == nullptr || *a > Mean(highest->wandering.ains).value_or(0.0)) highest = &row;
    }
  }
  std::string text = absl::StrCat(
      "**AS-BFO's iterations.** Its AIN in Table 4 is ",
      Range(PerCell(in, kReferenceMethod, MeanAin)),
      " with the wandering initial paths of the main rows, the paper's ", Range(paper_ain),
      "; with near-A* initial paths (the ablation) it is ", Range(PerCell(in, ablation, MeanAin)),
      ", since one of those is often the optimum already. Over the sweeps' values it is ",
      Range(sweep_wandering), " with wandering and ", Range(sweep_default),
      " with near-A* initial paths");
  if (highest != nullptr) {
    absl::StrAppend(&text, " (wandering: highest at ", highest->sweep->symbol, " = ",
                    highest->value, ")");
  }
  absl::StrAppend(&text, ".\n\n");
  return text;
}

std::string AcoParagraph(const DiscussionInputs& in) {
  const size_t aco = MethodIndex("aco-grid", false);
  const std::string& ref = Methods()[kReferenceMethod].label;
  const std::string& label = Methods()[aco].label;
  const MethodFindings f = FindingsOf(in, aco);
  const int cells = CellCount(in);
  int not_worse = 0;
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    for (size_t s = 0; s < in.worlds[e].size(); ++s) {
      const auto a = Mean(in.outcomes[e][kReferenceMethod][s].lengths);
      const auto b = Mean(in.outcomes[e][aco][s].lengths);
      if (a && b && *a <= *b + 1e-9) ++not_worse;
    }
  }
  std::string text = absl::StrCat(
      "**", ref, " against ", label, ".** ", ref, "'s APL is at most ", label, "'s in ", not_worse,
      "/", cells, " cells. The tests (section \"Table 4: tests against ", ref, "\") find ", label,
      "'s paths longer in ", f.longer.Or("no cell"), "; ", label, " at the optimum less often in ",
      f.fewer_optimal.Or("no cell"), "; its AIN higher in ", f.more_iterations.Or("no cell"), ". ",
      label, " is significantly better than ", ref, " in ");
  std::string better;
  AppendListItem(&better, f.shorter.count ? "length: " + f.shorter.cells : "", "; ");
  AppendListItem(&better, f.more_optimal.count ? "optimal runs: " + f.more_optimal.cells : "",
                 "; ");
  AppendListItem(&better, f.fewer_iterations.count ? "AIN: " + f.fewer_iterations.cells : "", "; ");
  absl::StrAppend(&text, better.empty() ? "no cell" : better, ".");
  // Which of the paper's methods miss the optimum on average.
  std::string missing, exact;
  for (size_t m = 0; m < Methods().size(); ++m) {
    if (Methods()[m].paper_row < 0) continue;
    std::string where;
    double worst = 1.0;
    std::string worst_cell;
    for (size_t e = 0; e < in.worlds.size(); ++e) {
      for (size_t s = 0; s < in.worlds[e].size(); ++s) {
        const World& w = in.worlds[e][s];
        const auto apl = Mean(in.outcomes[e][m][s].lengths);
        if (!apl || *apl <= w.optimum + 1e-9) continue;
        AppendListItem(&where, Short(w));
        if (*apl / w.optimum > worst) {
          worst = *apl / w.optimum;
          worst_cell = Short(w);
        }
      }
    }
    if (where.empty()) {
      AppendListItem(&exact, Methods()[m].label);
    } else {
      AppendListItem(&missing,
                     absl::StrCat(Methods()[m].label, " in ", where, " (APL up to ",
                                  Percent(worst - 1.0), " above A*, ", worst_cell, ")"),
                     "; ");
    }
  }
  absl::StrAppend(
      &text, " Of the paper's three methods, ",
      missing.empty() ? "none misses A*'s optimum on average"
                      : absl::StrCat("these miss A*'s optimum on average: ", missing),
      exact.empty() ? "" : absl::StrCat("; APL equal to A*'s optimum in every cell: ", exact), ".");
  // ACO's AIN over the sizes, ours and the paper's.
  absl::StrAppend(&text, " ", label, "'s AIN over the sizes:");
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    std::vector<int> sizes;
    std::vector<double> ours, theirs;
    for (size_t s = 0; s < in.worlds[e].size(); ++s) {
      sizes.push_back(in.worlds[e][s].n);
      ours.push_back(Mean(in.outcomes[e][aco][s].ains).value_or(0.0));
      theirs.push_back(paper::kAin[e][Methods()[aco].paper_row][PaperSize(in.worlds[e][s].n)]);
    }
    absl::StrAppend(&text, e == 0 ? " " : "; ", "environment ", e + 1, " ours ", Shape(ours, sizes),
                    ", the paper's ", Shape(theirs, sizes));
  }
  absl::StrAppend(&text, ".\n\n");
  return text;
}

std::string GaParagraph(const DiscussionInputs& in) {
  const size_t ga = MethodIndex("ga", false);
  const std::string& ref = Methods()[kReferenceMethod].label;
  const std::string& label = Methods()[ga].label;
  const int row = Methods()[ga].paper_row;
  double paper_excess = 0.0;
  std::vector<double> paper_ain;
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    for (const World& w : in.worlds[e]) {
      const int s = PaperSize(w.n);
      paper_excess =
          std::max(paper_excess, paper::kMeanLength[e][row][s] / paper::kMinLength[e][0][s] - 1.0);
      paper_ain.push_back(paper::kAin[e][row][s]);
    }
  }
  int optimal = 0, runs = 0, first = 0, found = 0;
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    for (size_t s = 0; s < in.worlds[e].size(); ++s) {
      const Outcome& o = in.outcomes[e][ga][s];
      optimal += OptimalRuns(o, in.worlds[e][s].optimum);
      runs += o.runs;
      first += static_cast<int>(std::count(o.ains.begin(), o.ains.end(), 1.0));
      found += static_cast<int>(o.ains.size());
    }
  }
  const MethodFindings f = FindingsOf(in, ga);
  std::string differences;
  for (const auto& [list, what] : {std::pair{&f.longer, "longer paths"},
                                   {&f.shorter, "shorter paths"},
                                   {&f.fewer_optimal, "fewer optimal runs"},
                                   {&f.more_optimal, "more optimal runs"},
                                   {&f.more_iterations, "a higher AIN"},
                                   {&f.fewer_iterations, "a lower AIN"}}) {
    if (list->count > 0)
      AppendListItem(&differences, absl::StrCat(what, " in ", list->cells), "; ");
  }
  // The ablation rows: near-A* initial paths.
  std::vector<double> excess, first_counts;
  int ablation_runs = 0;
  for (size_t m = 0; m < Methods().size(); ++m) {
    if (Methods()[m].paper_row >= 0) continue;
    for (size_t e = 0; e < in.worlds.size(); ++e) {
      for (size_t s = 0; s < in.worlds[e].size(); ++s) {
        const Outcome& o = in.outcomes[e][m][s];
        if (auto apl = Mean(o.lengths)) excess.push_back(*apl / in.worlds[e][s].optimum - 1.0);
        first_counts.push_back(std::count(o.ains.begin(), o.ains.end(), 1.0));
        ablation_runs = o.runs;
      }
    }
  }
  std::vector<double> ga_excess = PerCell(in, ga, [](const Outcome& o, const World& w) {
    const std::optional<double> apl = Mean(o.lengths);
    return apl ? std::optional<double>(*apl / w.optimum - 1.0) : std::nullopt;
  });
  std::string text = absl::StrCat(
      "**Where we do not agree.** (1) The paper's ", label, " is clearly worse than ", ref,
      " (APL up to ", Percent(paper_excess), " above the best, AIN ", Range(paper_ain), "). Ours, ",
      "from the same wandering initial paths as ", ref, ", reaches A*'s optimum in ", optimal,
      " of ", runs, " runs (APL at most ", Percent(Max(ga_excess).value_or(0.0)),
      " above it) and has its final best in iteration 1 in ", first, " of ", found, "; against ",
      ref, " the tests find ",
      differences.empty() ? absl::StrCat("no difference in any of the ", CellCount(in), " cells")
                          : differences,
      ". Our initial paths, shared by `as-bfo` and `ga`, run through random cells joined by A*: "
      "however many cells they pass (up to ",
      kWanderingVia,
      " here), every leg between two of them is optimal and loop removal cuts the detours, so "
      "the operators start close to the optimum. The paper only says its initial paths are "
      "\"randomly generated without infeasible paths\"; if they were random walks, its operators "
      "had far more to repair, which is where its differences come from. With near-A* initial "
      "paths (1–",
      kDefaultVia, " cells, the ablation rows) the search has even less to do: APL within ",
      Percent(Max(excess).value_or(0.0)), " of the optimum, final best in the first iteration in ",
      CountRange(first_counts), " of ", ablation_runs, " runs per cell.");
  return text;
}

std::string LargeMapsAndLengthsParagraph(const DiscussionInputs& in) {
  const size_t aco = MethodIndex("aco-grid", false);
  const int row = Methods()[aco].paper_row;
  std::vector<double> paper_ratio, paper_ain, ours_excess;
  for (size_t e = 0; e < paper::kEnvironments; ++e) {
    for (int s = paper::kSizes - 2; s < paper::kSizes; ++s) {
      paper_ratio.push_back(paper::kMeanLength[e][row][s] / paper::kMinLength[e][0][s]);
      paper_ain.push_back(paper::kAin[e][row][s]);
    }
  }
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    for (size_t s = 0; s < in.worlds[e].size(); ++s) {
      if (PaperSize(in.worlds[e][s].n) < paper::kSizes - 2) continue;
      if (auto apl = Mean(in.outcomes[e][aco][s].lengths)) {
        ours_excess.push_back(*apl / in.worlds[e][s].optimum - 1.0);
      }
    }
  }
  std::string text =
      absl::StrCat(" (2) The paper's ", Methods()[aco].label, " degrades badly at S4–S5 (APL ",
                   Range(paper_ratio, 3, "×"), " the best, AIN ", Range(paper_ain), ")");
  if (!ours_excess.empty()) {
    absl::StrAppend(&text, "; ours stays within ", Percent(*Max(ours_excess)), " of A* there");
  }
  absl::StrAppend(&text,
                  ". Its parameters are not published, and its low AIN there suggests early "
                  "stagnation; ours uses α = 1, β = 7 (a strong pull to the goal) and 100 "
                  "iterations. (3) Lengths are not comparable number for number: the paper's maps "
                  "are not published (its shortest S1 paths are ");
  std::string theirs, ours;
  for (size_t e = 0; e < in.worlds.size(); ++e) {
    double shortest = paper::kMinLength[e][0][0];
    for (int m = 0; m < paper::kMethods; ++m)
      shortest = std::min(shortest, paper::kMinLength[e][m][0]);
    AppendListItem(&theirs, NumberCell(shortest), " and ");
    for (const World& w : in.worlds[e]) {
      if (PaperSize(w.n) == 0) AppendListItem(&ours, NumberCell(w.optimum), " and ");
    }
  }
  absl::StrAppend(&text, theirs, " long, our S1 optima ", ours,
                  "), so only the distance to A* and the ranking carry over.\n\n");
  return text;
}

std::string PaperTableParagraph() {
  static const char* const kMethodNames[] = {"AS-BFO", "ACO", "GA"};
  std::string flaws;
  for (int e = 0; e < paper::kEnvironments; ++e) {
    for (int m = 0; m < paper::kMethods; ++m) {
      for (int s = 0; s < paper::kSizes; ++s) {
        const double min = paper::kMinLength[e][m][s], max = paper::kMaxLength[e][m][s],
                     apl = paper::kMeanLength[e][m][s];
        const std::string where =
            absl::StrCat(kMethodNames[m], " in environment ", e + 1, ", S", s + 1, " has ");
        if (apl < min - 1e-9) {
          AppendListItem(&flaws,
                         absl::StrCat(where, "MinPL = ", NumberCell(min),
                                      " but APL = ", NumberCell(apl), ", below its minimum"),
                         "; ");
        } else if (apl > max + 1e-9) {
          AppendListItem(&flaws,
                         absl::StrCat(where, "MaxPL = ", NumberCell(max),
                                      " but APL = ", NumberCell(apl), ", above its maximum"),
                         "; ");
        } else if (std::abs(apl - max) < 1e-9 && max > min + 1e-9) {
          AppendListItem(&flaws,
                         absl::StrCat(where, "MaxPL = APL = ", NumberCell(max),
                                      ", which needs every run at the maximum, while "
                                      "MinPL is ",
                                      NumberCell(min)),
                         "; ");
        }
      }
    }
  }
  if (flaws.empty()) return "";
  return absl::StrCat("**The paper's table itself** has impossible cells: ", flaws,
                      ". We copied the numbers as printed.\n\n");
}

std::string PaperClaimsParagraph(const DiscussionInputs& in) {
  const std::string& ref = Methods()[kReferenceMethod].label;
  const int cells = CellCount(in);
  std::string text = absl::StrCat(
      "**The paper's Table 4 claims, tested** (", cells,
      " cells; a cell counts when p < 0.05):\n\n- \"the AS-BFO has a better average path length "
      "using a very small iteration number\": ");
  std::string lengths, iterations, max_lengths, min_lengths, gaps;
  for (size_t m : TestedMethods()) {
    const std::string& label = Methods()[m].label;
    const MethodFindings f = FindingsOf(in, m);
    AppendListItem(&lengths, absl::StrCat(ref, " shorter than ", label, " in ", f.longer.count,
                                          ", longer in ", f.shorter.count));
    AppendListItem(&iterations,
                   absl::StrCat("AIN lower than ", label, "'s in ", f.more_iterations.count,
                                ", higher in ", f.fewer_iterations.count));
    // The single best and worst runs, by the permutation test of the minima and maxima.
    for (const bool maximum : {true, false}) {
      int below = 0, below_significant = 0, above_significant = 0;
      for (size_t e = 0; e < in.worlds.size(); ++e) {
        for (size_t s = 0; s < in.worlds[e].size(); ++s) {
          const Outcome& base = in.outcomes[e][kReferenceMethod][s];
          const Outcome& other = in.outcomes[e][m][s];
          const auto a = maximum ? Max(base.lengths) : Min(base.lengths);
          const auto b = maximum ? Max(other.lengths) : Min(other.lengths);
          if (!a || !b) continue;
          const MethodTests t = TestAgainst(base, other, in.worlds[e][s].optimum);
          const bool significant = Significant(maximum ? t.max_p : t.min_p);
          if (*a < *b - 1e-9) {
            ++below;
            below_significant += significant ? 1 : 0;
          } else if (*a > *b + 1e-9) {
            above_significant += significant ? 1 : 0;
          }
        }
      }
      AppendListItem(
          maximum ? &max_lengths : &min_lengths,
          absl::StrCat("below ", label, "'s in ", below, "/", cells, " cells, significantly in ",
                       below_significant, " (significantly above in ", above_significant, ")"),
          "; ");
    }
    for (size_t e = 0; e < in.worlds.size(); ++e) {
      std::vector<int> sizes;
      std::vector<double> gap;
      for (size_t s = 0; s < in.worlds[e].size(); ++s) {
        const World& w = in.worlds[e][s];
        sizes.push_back(w.n);
        gap.push_back((Mean(in.outcomes[e][m][s].lengths).value_or(0.0) -
                       Mean(in.outcomes[e][kReferenceMethod][s].lengths).value_or(0.0)) /
                      w.optimum);
      }
      std::string list;
      for (double g : gap) AppendListItem(&list, Percent(g));
      AppendListItem(&gaps, absl::StrCat(label, " environment ", e + 1, ": ", list), "; ");
    }
  }
  absl::StrAppend(
      &text, lengths, "; ", iterations, ".\n",
      "- \"the maximum path length obtained by AS-BFO is less than ACO and GA\": our MaxPL is ",
      max_lengths,
      ". Each MaxPL is a single run, so it is tested by the permutation test of the maxima "
      "(section \"Table 4: tests against ",
      ref, "\").\n",
      "- its best runs (\"AS-BFO's MinPL is … smaller than ACO and … GA\", S4 and S5): our MinPL "
      "is ",
      min_lengths, ", by the permutation test of the minima.\n",
      "- \"the larger the map size L, the greater the advantage of AS-BFO\": the APL gap to ", ref,
      " over A*'s optimum from the smallest size to the largest is ", gaps,
      "; the cells where the tests find a difference are listed above.\n\n");
  return text;
}

// The paper's best single values of the sweeps, tested against the other values.
std::string BestValuesText(const std::vector<SweepRow>& rows) {
  const std::string verdicts = PaperBestValueVerdicts(rows);
  if (verdicts.empty()) {
    return "Its best single values (the table above) cannot be tested here: one value per "
           "parameter.\n\n";
  }
  return absl::StrCat(
      "Its best single values (the table above) differ between its two environments; each value "
      "it names for environment 2 (our sweep world's) against every other value of its sweep, "
      "with wandering initial paths:\n\n",
      verdicts, "\n");
}

std::string SweepParagraph(const DiscussionInputs& in) {
  std::vector<double> optimal_default, optimal_wandering, ain_default, ain_wandering;
  int runs = 0;
  for (const SweepRow& row : in.sweep_rows) {
    optimal_default.push_back(OptimalRuns(row.outcome, in.sweep_world.optimum));
    optimal_wandering.push_back(OptimalRuns(row.wandering, in.sweep_world.optimum));
    if (auto a = Mean(row.outcome.ains)) ain_default.push_back(*a);
    if (auto a = Mean(row.wandering.ains)) ain_wandering.push_back(*a);
    runs = row.outcome.runs;
  }
  const std::string default_differences = SweepDifferences(in.sweep_ends, false);
  const std::string wandering_differences = SweepDifferences(in.sweep_ends, true);
  const std::string none = in.sweep_ends.empty()
                               ? "nothing to test (one value per parameter)"
                               : "no difference between any parameter's smallest and largest value";
  return absl::StrCat(
      "**Sweeps.** With near-A* initial paths every value reaches the optimum in ",
      CountRange(optimal_default), " of ", runs, " runs, with AIN ", Range(ain_default),
      "; the tests find ", default_differences.empty() ? none : default_differences,
      ". With wandering initial paths: the optimum in ", CountRange(optimal_wandering), " of ",
      runs, " runs, AIN ", Range(ain_wandering), "; the tests find ",
      wandering_differences.empty() ? none : wandering_differences,
      ". Nc, Nre and Ned also set the iteration budget Nc·Nre·Ned. The paper's statements on the "
      "parameters, against the tests of the smallest and largest value:\n\n",
      SweepClaimVerdicts(in.sweep_ends), "\n", BestValuesText(in.sweep_rows));
}

}  // namespace

std::string Discussion(const DiscussionInputs& in) {
  std::string text = "## Discussion\n\n";
  if (in.quick) {
    absl::StrAppend(&text,
                    "*Computed from the quick run's few runs: its figures say nothing about the "
                    "planners.*\n\n");
  }
  absl::StrAppend(&text, IterationsParagraph(in), AcoParagraph(in), GaParagraph(in),
                  LargeMapsAndLengthsParagraph(in), PaperTableParagraph(), PaperClaimsParagraph(in),
                  SweepParagraph(in));
  absl::StrAppend(&text, MorrisParagraph(in.morris));
  absl::StrAppend(&text, "**On ", in.replicated_worlds, " drawn worlds per environment** (",
                  in.replicated_runs, " runs per method and world, section \"Table 4 on ",
                  in.replicated_worlds, " worlds per environment\"): the differences from ",
                  Methods()[kReferenceMethod].label, " the tests support are ",
                  in.replicated_differences.empty() ? "none" : in.replicated_differences, ".\n\n");
  return text;
}

}  // namespace swarmplan::bench::as_bfo_islands
