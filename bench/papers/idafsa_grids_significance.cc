#include "bench/papers/idafsa_grids_significance.h"

#include "absl/strings/str_cat.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench {
namespace {

std::string SuccessCell(const SuccessCount& s) { return absl::StrCat(s.successes, " / ", s.runs); }

std::string LabelWithP(const std::string& label, double p) {
  return absl::StrCat(label, " (", FormatPValue(p, /*mark_significant=*/false), ")");
}

bool LowerMedian(const std::vector<double>& a, const std::vector<double>& b) {
  return Median(a).value_or(0.0) < Median(b).value_or(0.0);
}

}  // namespace

ComparedRuns CompareRunsOf(const std::string& label, const FishRunStats& stats) {
  return {label, SuccessCount{stats.successes(), stats.runs}, stats.lengths, stats.turning_points};
}

ComparisonTests TestAgainst(const ComparedRuns& reference, const ComparedRuns& other) {
  return {SuccessP(reference.success, other.success), RankSumP(reference.lengths, other.lengths),
          RankSumP(reference.turning_points, other.turning_points)};
}

std::string ComparisonTable(const ComparedRuns& reference, const std::vector<ComparedRuns>& others,
                            const std::string& length_heading) {
  MarkdownTable table({"configuration", "success", "Fisher p", length_heading, "rank-sum p",
                       "median turning points [95% CI]", "rank-sum p"});
  table.AddRow({absl::StrCat(reference.label, " (reference)"), SuccessCell(reference.success), "",
                MedianWithInterval(reference.lengths), "",
                MedianWithInterval(reference.turning_points, 3), ""});
  for (const ComparedRuns& other : others) {
    const ComparisonTests tests = TestAgainst(reference, other);
    table.AddRow({other.label, SuccessCell(other.success), PValueCell(tests.success_p),
                  MedianWithInterval(other.lengths), PValueCell(tests.length_p),
                  MedianWithInterval(other.turning_points, 3), PValueCell(tests.turning_p)});
  }
  return table.ToString();
}

std::string SupportedDifferences(const ComparedRuns& reference,
                                 const std::vector<ComparedRuns>& others) {
  std::string list;
  for (const ComparedRuns& other : others) {
    const ComparisonTests tests = TestAgainst(reference, other);
    AppendListItem(
        &list, SuccessDifference(other.label, reference.success, other.success, tests.success_p));
    AppendListItem(&list, ValueDifference(other.label, "length", reference.lengths, other.lengths,
                                          tests.length_p));
    AppendListItem(&list, ValueDifference(other.label, "turning points", reference.turning_points,
                                          other.turning_points, tests.turning_p));
  }
  return list.empty() ? "none" : list;
}

std::string ClaimVerdict(const std::string& claim, const std::vector<ClaimTest>& tests,
                         const std::string& why_untestable) {
  std::string supported, reversed, not_shown, untestable;
  for (const ClaimTest& test : tests) {
    if (!test.p.has_value()) {
      AppendListItem(&untestable, test.baseline);
    } else if (*test.p >= kSignificanceLevel) {
      AppendListItem(&not_shown, LabelWithP(test.baseline, *test.p));
    } else {
      AppendListItem(test.idafsa_better ? &supported : &reversed,
                     LabelWithP(test.baseline, *test.p));
    }
  }
  std::string verdict;
  if (!supported.empty()) {
    AppendListItem(&verdict, absl::StrCat("supported against ", supported), "; ");
  }
  if (!reversed.empty()) {
    AppendListItem(&verdict,
                   absl::StrCat("reversed (idafsa significantly worse) against ", reversed), "; ");
  }
  if (!not_shown.empty()) {
    AppendListItem(&verdict, absl::StrCat("not significant against ", not_shown), "; ");
  }
  if (!untestable.empty()) {
    AppendListItem(
        &verdict, absl::StrCat("untestable against ", untestable, " (", why_untestable, ")"), "; ");
  }
  return absl::StrCat(claim, ": ", verdict.empty() ? "no baseline" : verdict, ".");
}

std::string HeadlineVerdict(const ComparedRuns& idafsa,
                            const std::vector<ComparedRuns>& baselines) {
  std::vector<ClaimTest> shorter, fewer_turns, more_successes;
  for (const ComparedRuns& other : baselines) {
    const ComparisonTests tests = TestAgainst(idafsa, other);
    shorter.push_back({other.label, tests.length_p, LowerMedian(idafsa.lengths, other.lengths)});
    fewer_turns.push_back(
        {other.label, tests.turning_p, LowerMedian(idafsa.turning_points, other.turning_points)});
    more_successes.push_back(
        {other.label, tests.success_p, idafsa.success.rate() > other.success.rate()});
  }
  const std::string no_path = "a side without successful runs";
  return absl::StrCat(ClaimVerdict("Shorter paths", shorter, no_path), " ",
                      ClaimVerdict("Fewer turning points", fewer_turns, no_path), " ",
                      ClaimVerdict("Higher success", more_successes, "no runs"));
}

}  // namespace swarmplan::bench
