#include "bench/papers/as_bfo_islands_sweep_tests.h"

#include "absl/strings/str_cat.h"
#include "bench/papers/as_bfo_islands_runs.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

// What the paper says of a parameter: larger values give shorter paths and / or fewer
// iterations.
struct SweepClaim {
  std::string symbol;
  std::string quote;
  bool shorter = false;
  bool faster = false;
};

const std::vector<SweepClaim>& SweepClaims() {
  static const std::vector<SweepClaim>* const claims = new std::vector<SweepClaim>{
      {"P", "bacteria number is inversely proportional to the path length", true, false},
      {"P", "the greater the number of bacteria, the faster the convergence rate", false, true},
      {"Nc",
       "the greater the chemotaxis number, the stronger is the local optimisation ability of the "
       "algorithm. Correspondingly, the path length and iteration number will decrease",
       true, true},
      {"Nre",
       "the greater the reproduction number, the smaller the diversity of the population and the "
       "faster the convergence of the algorithm",
       false, true},
      {"Ned",
       "the increase of elimination–dispersal number will decrease both the path length and "
       "iteration number within a certain range",
       true, true},
  };
  return *claims;
}

std::string EndsName(const SweepEnds& ends) {
  const std::string& symbol = ends.smallest->sweep->symbol;
  return absl::StrCat(symbol, " = ", ends.largest->value, " against ", symbol, " = ",
                      ends.smallest->value);
}

std::string PText(std::optional<double> p) {
  return p ? FormatPValue(*p, /*mark_significant=*/false) : "no test";
}

// "lengths lower (p = 0.002)" when the test supports a difference; empty otherwise.
std::string RankDifference(const std::string& what, const RankComparison& comparison) {
  if (!Significant(comparison.p)) return "";
  return absl::StrCat(what, comparison.other_higher ? " higher" : " lower", " (",
                      PText(comparison.p), ")");
}

std::string OptimalDifference(const MethodTests& tests) {
  if (!Significant(tests.optimal_p)) return "";
  return absl::StrCat("optimum reached ", tests.fewer_optimal ? "less" : "more", " often (",
                      PText(tests.optimal_p), ")");
}

std::string Differences(const MethodTests& tests) {
  std::string list;
  AppendListItem(&list, RankDifference("lengths", tests.length));
  AppendListItem(&list, OptimalDifference(tests));
  AppendListItem(&list, RankDifference("AIN", tests.ain));
  return list;
}

// Whether one kind of runs supports "larger values give shorter paths" / "fewer iterations".
std::string Verdict(const MethodTests& tests, const SweepClaim& claim) {
  std::string supported, contradicted, untold;
  if (claim.shorter) {
    const bool shorter = Significant(tests.length.p) && !tests.length.other_higher;
    const bool longer = Significant(tests.length.p) && tests.length.other_higher;
    const bool more_optimal = Significant(tests.optimal_p) && !tests.fewer_optimal;
    const bool fewer_optimal = Significant(tests.optimal_p) && tests.fewer_optimal;
    const std::string lengths =
        absl::StrCat("lengths ", PText(tests.length.p), ", optimal runs ", PText(tests.optimal_p));
    if (shorter || more_optimal) {
      AppendListItem(&supported, absl::StrCat("shorter paths (", lengths, ")"));
    } else if (longer || fewer_optimal) {
      AppendListItem(&contradicted, absl::StrCat("longer paths (", lengths, ")"));
    } else {
      AppendListItem(&untold, absl::StrCat("path length (", lengths, ")"));
    }
  }
  if (claim.faster) {
    const std::string ain = absl::StrCat("AIN ", PText(tests.ain.p));
    if (Significant(tests.ain.p) && !tests.ain.other_higher) {
      AppendListItem(&supported, absl::StrCat("fewer iterations (", ain, ")"));
    } else if (Significant(tests.ain.p)) {
      AppendListItem(&contradicted, absl::StrCat("more iterations (", ain, ")"));
    } else {
      AppendListItem(&untold, absl::StrCat("iterations (", ain, ")"));
    }
  }
  std::string verdict;
  if (!supported.empty()) AppendListItem(&verdict, "supported: " + supported, "; ");
  if (!contradicted.empty()) AppendListItem(&verdict, "contradicted: " + contradicted, "; ");
  if (!untold.empty()) AppendListItem(&verdict, "no difference in " + untold, "; ");
  return verdict;
}

}  // namespace

std::vector<SweepEnds> SweepEndsOf(const std::vector<SweepRow>& rows, double optimum) {
  std::vector<SweepEnds> out;
  for (const Sweep& sweep : Sweeps()) {
    const SweepRow* smallest = nullptr;
    const SweepRow* largest = nullptr;
    for (const SweepRow& row : rows) {
      if (row.sweep != &sweep) continue;
      if (smallest == nullptr || row.value < smallest->value) smallest = &row;
      if (largest == nullptr || row.value > largest->value) largest = &row;
    }
    if (smallest == nullptr || smallest == largest) continue;
    out.push_back({smallest, largest, TestAgainst(smallest->outcome, largest->outcome, optimum),
                   TestAgainst(smallest->wandering, largest->wandering, optimum)});
  }
  return out;
}

std::string SweepTestsSection(const std::vector<SweepEnds>& ends, double optimum) {
  std::string text = "### Tests: smallest against largest value\n\n";
  if (ends.empty()) {
    absl::StrAppend(&text, "No sweep ran more than one value: nothing to test.\n\n");
    return text;
  }
  absl::StrAppend(&text,
                  "Each parameter's largest value against its smallest, with either kind of "
                  "initial paths: the runs that reach the optimum by Fisher's exact test, lengths "
                  "and AIN by the rank-sum test; medians with bootstrap 95% intervals.\n\n");
  MarkdownTable table({"parameter", "initial paths", "value", "optimal runs", "Fisher",
                       "median length [95% CI]", "rank-sum", "median AIN [95% CI]", "rank-sum"},
                      3);
  const std::string wandering = absl::StrCat("≤", kWanderingVia, " via");
  for (const SweepEnds& end : ends) {
    for (const bool wander : {false, true}) {
      const Outcome& small = wander ? end.smallest->wandering : end.smallest->outcome;
      const Outcome& large = wander ? end.largest->wandering : end.largest->outcome;
      const MethodTests& tests = wander ? end.wandering_tests : end.tests;
      const std::string& symbol = end.smallest->sweep->symbol;
      auto optimal = [&](const Outcome& o) {
        return absl::StrCat(OptimalRuns(o, optimum), "/", o.runs);
      };
      table.AddRow({symbol, wander ? wandering : "near-A*", absl::StrCat(end.smallest->value),
                    optimal(small), "", MedianWithInterval(small.lengths), "",
                    MedianWithInterval(small.ains, 3), ""});
      table.AddRow({symbol, wander ? wandering : "near-A*", absl::StrCat(end.largest->value),
                    optimal(large), PValueCell(tests.optimal_p), MedianWithInterval(large.lengths),
                    PValueCell(tests.length.p), MedianWithInterval(large.ains, 3),
                    PValueCell(tests.ain.p)});
    }
  }
  absl::StrAppend(&text, table.ToString(), "\n");
  return text;
}

std::string SweepClaimVerdicts(const std::vector<SweepEnds>& ends) {
  std::string text;
  for (const SweepClaim& claim : SweepClaims()) {
    const SweepEnds* end = nullptr;
    for (const SweepEnds& e : ends) {
      if (e.smallest->sweep->symbol == claim.symbol) end = &e;
    }
    absl::StrAppend(&text, "- ", claim.symbol, ": \"", claim.quote, "\": ");
    if (end == nullptr) {
      absl::StrAppend(&text, "untested (one value only).\n");
      continue;
    }
    absl::StrAppend(&text, EndsName(*end), ", near-A* initial paths: ", Verdict(end->tests, claim),
                    "; wandering: ", Verdict(end->wandering_tests, claim), ".\n");
  }
  return text;
}

std::string SweepDifferences(const std::vector<SweepEnds>& ends, bool wandering) {
  std::string list;
  for (const SweepEnds& end : ends) {
    const std::string differences = Differences(wandering ? end.wandering_tests : end.tests);
    if (!differences.empty()) {
      AppendListItem(&list, absl::StrCat(EndsName(end), ": ", differences), "; ");
    }
  }
  return list;
}

std::string PaperBestValueVerdicts(const std::vector<SweepRow>& rows) {
  std::string text;
  for (const Sweep& sweep : Sweeps()) {
    std::vector<const SweepRow*> values;
    for (const SweepRow& row : rows) {
      if (row.sweep == &sweep) values.push_back(&row);
    }
    if (values.size() < 2) continue;
    struct Named {
      int value;
      const char* what;    // "shortest", "fewest"
      const char* metric;  // "lengths", "AIN"
      std::vector<double> Outcome::*values;
    };
    for (const Named& named :
         {Named{sweep.paper_shortest_env2, "shortest", "lengths", &Outcome::lengths},
          Named{sweep.paper_fewest_env2, "fewest iterations", "AIN", &Outcome::ains}}) {
      const SweepRow* best = nullptr;
      const SweepRow* ours = nullptr;
      for (const SweepRow* row : values) {
        if (row->value == named.value) best = row;
        const std::optional<double> mean = Mean(row->wandering.*named.values);
        if (mean && (ours == nullptr || *mean < *Mean(ours->wandering.*named.values) - 1e-12)) {
          ours = row;
        }
      }
      if (best == nullptr) continue;
      int lower = 0, higher = 0;
      for (const SweepRow* other : values) {
        if (other == best) continue;
        const RankComparison c =
            CompareRanks(best->wandering.*named.values, other->wandering.*named.values);
        if (!Significant(c.p)) continue;
        ++(c.other_higher ? lower : higher);
      }
      absl::StrAppend(&text, "- ", sweep.symbol, " = ", named.value, " (the paper's ", named.what,
                      " in environment 2): its ", named.metric, " are lower than at ", lower,
                      " and higher than at ", higher, " of the ", values.size() - 1,
                      " other values (rank-sum, p < ", kSignificanceLevel, "); our lowest mean ",
                      named.metric == std::string("AIN") ? "AIN" : "APL", " is at ", sweep.symbol,
                      " = ", ours != nullptr ? absl::StrCat(ours->value) : "–", ".\n");
    }
  }
  return text;
}

}  // namespace swarmplan::bench::as_bfo_islands
