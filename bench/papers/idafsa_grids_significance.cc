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

ClaimOutcome OutcomeOf(const ClaimTest& test) {
  if (!test.p.has_value()) return ClaimOutcome::kUntestable;
  if (*test.p >= kSignificanceLevel) return ClaimOutcome::kNotSignificant;
  return test.idafsa_better ? ClaimOutcome::kSupported : ClaimOutcome::kReversed;
}

std::string OutcomeName(ClaimOutcome outcome) {
  switch (outcome) {
    case ClaimOutcome::kSupported:
      return "supported";
    case ClaimOutcome::kReversed:
      return "reversed";
    case ClaimOutcome::kNotSignificant:
      return "not significant";
    case ClaimOutcome::kUntestable:
      return "untestable";
  }
  return "untestable";
}

std::string ClaimVerdict(const std::string& claim, const std::vector<ClaimTest>& tests,
                         const std::string& why_untestable) {
  std::string supported, reversed, not_shown, untestable;
  for (const ClaimTest& test : tests) {
    switch (OutcomeOf(test)) {
      case ClaimOutcome::kUntestable:
        AppendListItem(&untestable, test.baseline);
        break;
      case ClaimOutcome::kNotSignificant:
        AppendListItem(&not_shown, LabelWithP(test.baseline, *test.p));
        break;
      case ClaimOutcome::kSupported:
        AppendListItem(&supported, LabelWithP(test.baseline, *test.p));
        break;
      case ClaimOutcome::kReversed:
        AppendListItem(&reversed, LabelWithP(test.baseline, *test.p));
        break;
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

std::string ClaimVerdict(const ClaimTests& claim) {
  return ClaimVerdict(claim.claim, claim.tests, claim.why_untestable);
}

std::vector<ClaimTests> HeadlineClaims(const ComparedRuns& idafsa,
                                       const std::vector<ComparedRuns>& baselines) {
  const std::string no_path = "a side without successful runs";
  std::vector<ClaimTests> claims = {{"Shorter paths", no_path, {}},
                                    {"Fewer turning points", no_path, {}},
                                    {"Higher success", "no runs", {}}};
  for (const ComparedRuns& other : baselines) {
    const ComparisonTests tests = TestAgainst(idafsa, other);
    claims[0].tests.push_back(
        {other.label, tests.length_p, LowerMedian(idafsa.lengths, other.lengths)});
    claims[1].tests.push_back(
        {other.label, tests.turning_p, LowerMedian(idafsa.turning_points, other.turning_points)});
    claims[2].tests.push_back(
        {other.label, tests.success_p, idafsa.success.rate() > other.success.rate()});
  }
  return claims;
}

std::string HeadlineVerdict(const ComparedRuns& idafsa,
                            const std::vector<ComparedRuns>& baselines) {
  std::string verdict;
  for (const ClaimTests& claim : HeadlineClaims(idafsa, baselines)) {
    AppendListItem(&verdict, ClaimVerdict(claim), " ");
  }
  return verdict;
}

}  // namespace swarmplan::bench
