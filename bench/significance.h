#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// Significance tests for the reproductions' comparisons: whether a difference between two
// planners (or between our run and a claim) is larger than the runs' scatter explains.

namespace swarmplan::bench {

// Mann-Whitney U test (Wilcoxon rank-sum), two-sided: whether values of `a` tend to be larger or
// smaller than values of `b`.
struct RankSumTest {
  double u = 0.0;        // U of `a`: pairs (x in a, y in b) with x > y, ties counting 1/2
  double p_value = 1.0;  // two-sided
  bool exact = false;    // from the exact distribution of U (no ties, small samples)
};
// The exact permutation distribution of U when there are no ties and the samples hold at most
// kExactRankSumValues values together; otherwise the normal approximation with the tie
// correction of the variance and a continuity correction of 1/2 (as R's wilcox.test and SciPy's
// mannwhitneyu). nullopt when a sample is empty or a value is not finite.
inline constexpr int kExactRankSumValues = 60;
std::optional<RankSumTest> MannWhitneyU(const std::vector<double>& a, const std::vector<double>& b);

// Wilcoxon signed-rank test of paired samples, two-sided: whether the differences a[i] - b[i]
// tend to be positive or negative (e.g. two planners' median lengths on the same worlds).
// Zero differences are dropped (as R's wilcox.test). The exact distribution of V when the
// remaining differences are untied and at most kExactSignedRankPairs; otherwise the normal
// approximation with the tie correction and a continuity correction of 1/2. nullopt when the
// samples differ in size, are empty or hold a value that is not finite.
struct SignedRankTest {
  double v = 0.0;        // the sum of the ranks of |a[i] - b[i]| over the positive differences
  int pairs = 0;         // pairs with a nonzero difference
  double p_value = 1.0;  // two-sided; 1 when every difference is zero
  bool exact = false;
};
inline constexpr int kExactSignedRankPairs = 50;
std::optional<SignedRankTest> WilcoxonSignedRank(const std::vector<double>& a,
                                                 const std::vector<double>& b);

// Fisher's exact test on the 2 x 2 table of successes and failures of two samples, two-sided: the
// probability, under equal success rates and the observed margins, of a table no more likely
// than the observed one (relative tolerance 1e-7, as R and SciPy). nullopt when a count is
// negative or a sample's successes exceed its size.
std::optional<double> FisherExactTwoSided(int successes_a, int size_a, int successes_b, int size_b);

// A two-sided percentile bootstrap interval of the median: `resamples` resamples of `values`
// with replacement, drawn by a generator seeded with `seed` (the same values and seed give the
// same interval on every machine). nullopt when `values` is empty, `confidence` is not in
// (0, 1) or `resamples` < 1.
struct Interval {
  double low = 0.0;
  double high = 0.0;
};
std::optional<Interval> BootstrapMedianInterval(const std::vector<double>& values,
                                                double confidence = 0.95, int resamples = 10000,
                                                uint64_t seed = 1);

// The significance level the reports use: a difference counts when p < 0.05.
inline constexpr double kSignificanceLevel = 0.05;

// "p = 0.031" or "p = 2.1e-05", with " *" appended when p < kSignificanceLevel and
// `mark_significant`.
std::string FormatPValue(double p, bool mark_significant = true);

}  // namespace swarmplan::bench
