#include "bench/papers/comparison.h"

#include "absl/strings/str_cat.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench {

std::string MedianWithInterval(const std::vector<double>& values, int significant) {
  const std::optional<double> median = Median(values);
  const std::optional<Interval> interval = BootstrapMedianInterval(values);
  if (!median.has_value() || !interval.has_value()) return "–";
  return absl::StrCat(NumberCell(*median, significant), " [",
                      NumberCell(interval->low, significant), ", ",
                      NumberCell(interval->high, significant), "]");
}

std::optional<double> RankSumP(const std::vector<double>& a, const std::vector<double>& b) {
  const std::optional<RankSumTest> test = MannWhitneyU(a, b);
  if (!test.has_value()) return std::nullopt;
  return test->p_value;
}

std::optional<double> SignedRankP(const std::vector<double>& a, const std::vector<double>& b) {
  const std::optional<SignedRankTest> test = WilcoxonSignedRank(a, b);
  if (!test.has_value()) return std::nullopt;
  return test->p_value;
}

std::vector<double> DividedBy(const std::vector<double>& values, double divisor) {
  std::vector<double> out;
  out.reserve(values.size());
  for (double v : values) out.push_back(v / divisor);
  return out;
}

std::optional<double> SuccessP(const SuccessCount& a, const SuccessCount& b) {
  return FisherExactTwoSided(a.successes, a.runs, b.successes, b.runs);
}

std::string PValueCell(std::optional<double> p) { return p.has_value() ? FormatPValue(*p) : "–"; }

RankComparison CompareRanks(const std::vector<double>& reference,
                            const std::vector<double>& other) {
  RankComparison out;
  const std::optional<RankSumTest> test = MannWhitneyU(other, reference);
  if (!test.has_value()) return out;
  out.p = test->p_value;
  out.other_higher = test->u > 0.5 * static_cast<double>(other.size() * reference.size());
  return out;
}

bool Significant(std::optional<double> p) { return p.has_value() && *p < kSignificanceLevel; }

std::string ValueDifference(const std::string& other, const std::string& what,
                            const std::vector<double>& reference, const std::vector<double>& theirs,
                            std::optional<double> p) {
  if (!Significant(p)) return "";
  const bool higher = CompareRanks(reference, theirs).other_higher;
  return absl::StrCat(other, "'s ", what, higher ? " higher" : " lower", " (",
                      FormatPValue(*p, /*mark_significant=*/false), ")");
}

std::string SuccessDifference(const std::string& other, const SuccessCount& reference,
                              const SuccessCount& theirs, std::optional<double> p) {
  if (!Significant(p)) return "";
  return absl::StrCat(other, " found ", theirs.rate() > reference.rate() ? "more" : "fewer", " (",
                      FormatPValue(*p, /*mark_significant=*/false), ")");
}

void AppendListItem(std::string* list, const std::string& item, const char* separator) {
  if (item.empty()) return;
  absl::StrAppend(list, list->empty() ? "" : separator, item);
}

}  // namespace swarmplan::bench
