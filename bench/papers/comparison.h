#pragma once

// The statistics behind every reproduction's comparisons, formatted for its tables and its
// discussion: medians with bootstrap intervals and the tests of bench/significance.h, so a
// report states a difference only when a test supports it.

#include <optional>
#include <string>
#include <vector>

namespace swarmplan::bench {

// How many runs of one planner configuration succeeded.
struct SuccessCount {
  int successes = 0;
  int runs = 0;
  double rate() const { return runs > 0 ? static_cast<double>(successes) / runs : 0.0; }
};

// The median and its bootstrap 95 % interval, e.g. "117.2 [116.3, 118.0]"; "–" when empty.
std::string MedianWithInterval(const std::vector<double>& values, int significant = 4);

// The two-sided Mann-Whitney p-value of `a` against `b`; nullopt when a sample is empty.
std::optional<double> RankSumP(const std::vector<double>& a, const std::vector<double>& b);

// A rank-sum test of `other` against `reference`, with the direction of the difference: by U,
// whether values of `other` tend to be the larger ones (medians tie when most runs reach the
// same value, ranks do not).
struct RankComparison {
  std::optional<double> p;
  bool other_higher = false;
};
RankComparison CompareRanks(const std::vector<double>& reference, const std::vector<double>& other);

// p < kSignificanceLevel.
bool Significant(std::optional<double> p);

// The two-sided Wilcoxon signed-rank p-value of the pairs (a[i], b[i]); nullopt when the sizes
// differ or a sample is empty.
std::optional<double> SignedRankP(const std::vector<double>& a, const std::vector<double>& b);

// Every value divided by `divisor`, e.g. lengths over a world's optimum, so worlds can be pooled.
std::vector<double> DividedBy(const std::vector<double>& values, double divisor);

// Fisher's exact p-value on the success counts of `a` and `b`.
std::optional<double> SuccessP(const SuccessCount& a, const SuccessCount& b);

// "p = 0.031 *" in a table cell, "–" when there is no test.
std::string PValueCell(std::optional<double> p);

// One difference of `other` from the reference that a test supports, for a discussion:
// "pso's length higher (p = 0.003)" (by the ranks of the values) or "ba found fewer
// (p = 2e-05)"; empty when p is absent or not below kSignificanceLevel.
std::string ValueDifference(const std::string& other, const std::string& what,
                            const std::vector<double>& reference, const std::vector<double>& theirs,
                            std::optional<double> p);
std::string SuccessDifference(const std::string& other, const SuccessCount& reference,
                              const SuccessCount& theirs, std::optional<double> p);

// Appends `item` to a comma-separated list; nothing when `item` is empty.
void AppendListItem(std::string* list, const std::string& item, const char* separator = ", ");

}  // namespace swarmplan::bench
