#include "bench/significance.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench/statistics.h"
#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

// Reference values: SciPy's and R's documented examples, and (the tied sample) R's
// wilcox.test with its normal approximation.
TEST(MannWhitneyUTest, ExactPValuesOfPublishedExamples) {
  // SciPy's mannwhitneyu example: U = 17, p = 0.1111 (exact).
  std::optional<RankSumTest> test = MannWhitneyU({19, 22, 16, 29, 24}, {20, 11, 17, 12});
  ASSERT_TRUE(test.has_value());
  EXPECT_TRUE(test->exact);
  EXPECT_DOUBLE_EQ(test->u, 17.0);
  EXPECT_NEAR(test->p_value, 1.0 / 9.0, 1e-12);
  // R's wilcox.test example: W = 35, one-sided p = 0.1272, so two-sided 0.2544.
  test = MannWhitneyU({0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46},
                      {1.15, 0.88, 0.90, 0.74, 1.21});
  ASSERT_TRUE(test.has_value());
  EXPECT_TRUE(test->exact);
  EXPECT_DOUBLE_EQ(test->u, 35.0);
  EXPECT_NEAR(test->p_value, 0.2544122544122544, 1e-12);
}

TEST(MannWhitneyUTest, SwappingTheSamplesMirrorsUAndKeepsP) {
  const std::vector<double> a = {3.1, 4.7, 5.2, 6.0, 2.2, 8.4};
  const std::vector<double> b = {1.0, 2.5, 3.3, 0.4, 1.9};
  const std::optional<RankSumTest> ab = MannWhitneyU(a, b), ba = MannWhitneyU(b, a);
  ASSERT_TRUE(ab.has_value() && ba.has_value());
  EXPECT_DOUBLE_EQ(ab->u + ba->u, static_cast<double>(a.size() * b.size()));
  EXPECT_NEAR(ab->p_value, ba->p_value, 1e-12);
}

TEST(MannWhitneyUTest, TiesUseTheNormalApproximationWithTheTieCorrection) {
  const std::optional<RankSumTest> test =
      MannWhitneyU({1, 2, 2, 3, 3, 3, 4, 7}, {2, 3, 5, 5, 6, 8, 8, 9, 10});
  ASSERT_TRUE(test.has_value());
  EXPECT_FALSE(test->exact);
  EXPECT_DOUBLE_EQ(test->u, 12.5);
  EXPECT_NEAR(test->p_value, 0.025404337886846328, 1e-12);
}

TEST(MannWhitneyUTest, LargeSamplesUseTheNormalApproximation) {
  std::vector<double> a, b;
  for (int i = 0; i < 40; ++i) a.push_back(i);
  for (int i = 0; i < 30; ++i) b.push_back(i + 10.5);
  const std::optional<RankSumTest> test = MannWhitneyU(a, b);
  ASSERT_TRUE(test.has_value());
  EXPECT_FALSE(test->exact);
  EXPECT_DOUBLE_EQ(test->u, 435.0);
  EXPECT_NEAR(test->p_value, 0.05090783898652564, 1e-12);
}

// The exact distribution against an enumeration of every split of 13 untied values into 6 and 7.
TEST(MannWhitneyUTest, ExactPValueCountsEverySplit) {
  Rng rng(7);
  std::vector<double> pooled(13);
  for (double& v : pooled) v = rng.Normal(0.0, 1.0);
  const std::vector<double> a(pooled.begin(), pooled.begin() + 6);
  const std::vector<double> b(pooled.begin() + 6, pooled.end());
  auto u_of = [](const std::vector<double>& x, const std::vector<double>& y) {
    double u = 0.0;
    for (double xi : x) {
      for (double yi : y) u += xi > yi ? 1.0 : 0.0;
    }
    return u;
  };
  const double observed = u_of(a, b);
  int splits = 0, at_most = 0, at_least = 0;
  for (int mask = 0; mask < (1 << 13); ++mask) {
    if (__builtin_popcount(mask) != 6) continue;
    std::vector<double> x, y;
    for (int i = 0; i < 13; ++i) (mask >> i & 1 ? x : y).push_back(pooled[i]);
    const double u = u_of(x, y);
    ++splits;
    at_most += u <= observed;
    at_least += u >= observed;
  }
  ASSERT_EQ(splits, 1716);
  const std::optional<RankSumTest> test = MannWhitneyU(a, b);
  ASSERT_TRUE(test.has_value());
  EXPECT_TRUE(test->exact);
  EXPECT_DOUBLE_EQ(test->u, observed);
  EXPECT_NEAR(test->p_value, std::min(1.0, 2.0 * std::min(at_most, at_least) / splits), 1e-12);
}

TEST(MannWhitneyUTest, EqualValuesGiveNoEvidence) {
  const std::optional<RankSumTest> test = MannWhitneyU({2, 2, 2}, {2, 2});
  ASSERT_TRUE(test.has_value());
  EXPECT_DOUBLE_EQ(test->p_value, 1.0);
}

TEST(MannWhitneyUTest, RefusesEmptyOrNonFiniteSamples) {
  EXPECT_FALSE(MannWhitneyU({}, {1.0}).has_value());
  EXPECT_FALSE(MannWhitneyU({1.0, NAN}, {1.0}).has_value());
  EXPECT_FALSE(MannWhitneyU({1.0}, {INFINITY}).has_value());
}

TEST(WilcoxonSignedRankTest, ExactPValueOfRsPublishedExample) {
  // R's wilcox.test paired example (Hollander & Wolfe, depression scale before and after
  // therapy): V = 40, one-sided p = 0.01953, so two-sided 10 / 256.
  const std::vector<double> before = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
  const std::vector<double> after = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
  std::optional<SignedRankTest> test = WilcoxonSignedRank(before, after);
  ASSERT_TRUE(test.has_value());
  EXPECT_TRUE(test->exact);
  EXPECT_EQ(test->pairs, 9);
  EXPECT_DOUBLE_EQ(test->v, 40.0);
  EXPECT_NEAR(test->p_value, 10.0 / 256.0, 1e-12);
  test = WilcoxonSignedRank(after, before);
  ASSERT_TRUE(test.has_value());
  EXPECT_DOUBLE_EQ(test->v, 45.0 - 40.0);
  EXPECT_NEAR(test->p_value, 10.0 / 256.0, 1e-12);
}

TEST(WilcoxonSignedRankTest, ExactPValueCountsEverySignAssignment) {
  Rng rng(7);
  for (int n : {1, 4, 8, 11}) {
    std::vector<double> a(n), b(n, 0.0);
    for (double& v : a) v = rng.Uniform(-1.0, 1.0);
    const std::optional<SignedRankTest> test = WilcoxonSignedRank(a, b);
    ASSERT_TRUE(test.has_value());
    ASSERT_TRUE(test->exact);
    // Under the null every assignment of signs to the ranks 1..n is equally likely: count
    // those whose V lies as far from its mean as the observed one.
    const double mean = n * (n + 1) / 4.0;
    int as_extreme = 0;
    for (int signs = 0; signs < (1 << n); ++signs) {
      double v = 0.0;
      for (int rank = 1; rank <= n; ++rank) {
        if (signs & (1 << (rank - 1))) v += rank;
      }
      if (std::abs(v - mean) >= std::abs(test->v - mean) - 1e-9) ++as_extreme;
    }
    EXPECT_NEAR(test->p_value, static_cast<double>(as_extreme) / (1 << n), 1e-12) << n;
  }
}

TEST(WilcoxonSignedRankTest, TiesAndZerosUseTheCorrectedNormalApproximation) {
  // Differences 1, 2, 2, -3, 4 and a zero that is dropped: midranks 1, 2.5, 2.5, 4, 5, V = 11;
  // mean 7.5, variance 5 * 6 * 11 / 24 - (2^3 - 2) / 48 = 13.625, z = (3.5 - 0.5) / sqrt(13.625).
  const std::optional<SignedRankTest> test =
      WilcoxonSignedRank({1, 2, 2, 0, 4, 7}, {0, 0, 0, 3, 0, 7});
  ASSERT_TRUE(test.has_value());
  EXPECT_FALSE(test->exact);
  EXPECT_EQ(test->pairs, 5);
  EXPECT_DOUBLE_EQ(test->v, 11.0);
  EXPECT_NEAR(test->p_value, 0.4163656779081653, 1e-12);
}

TEST(WilcoxonSignedRankTest, NoDifferencesAndBadSamples) {
  const std::optional<SignedRankTest> equal = WilcoxonSignedRank({1, 2, 3}, {1, 2, 3});
  ASSERT_TRUE(equal.has_value());
  EXPECT_EQ(equal->pairs, 0);
  EXPECT_DOUBLE_EQ(equal->p_value, 1.0);
  EXPECT_FALSE(WilcoxonSignedRank({}, {}).has_value());
  EXPECT_FALSE(WilcoxonSignedRank({1, 2}, {1}).has_value());
  EXPECT_FALSE(WilcoxonSignedRank({1, std::nan("")}, {1, 2}).has_value());
}

TEST(FisherExactTest, PublishedExamples) {
  // The lady tasting tea: 3 of 4 against 1 of 4, p = 34 / 70.
  EXPECT_NEAR(*FisherExactTwoSided(3, 4, 1, 4), 34.0 / 70.0, 1e-12);
  // SciPy's fisher_exact example [[6, 2], [1, 4]]: p = 0.1026.
  EXPECT_NEAR(*FisherExactTwoSided(6, 8, 1, 5), 0.10256410256410256, 1e-12);
  // R's fisher.test on [[8, 2], [1, 5]]: p = 0.03497.
  EXPECT_NEAR(*FisherExactTwoSided(8, 10, 1, 6), 0.03496503496503496, 1e-12);
  // 26 of 30 against 21 of 30 runs: not significant.
  EXPECT_NEAR(*FisherExactTwoSided(26, 30, 21, 30), 0.2092362789627995, 1e-12);
}

TEST(FisherExactTest, EqualRatesAndDegenerateTables) {
  EXPECT_DOUBLE_EQ(*FisherExactTwoSided(15, 30, 15, 30), 1.0);
  EXPECT_DOUBLE_EQ(*FisherExactTwoSided(30, 30, 30, 30), 1.0);
  EXPECT_DOUBLE_EQ(*FisherExactTwoSided(0, 0, 0, 5), 1.0);
  EXPECT_LT(*FisherExactTwoSided(30, 30, 0, 30), 1e-15);
}

TEST(FisherExactTest, RefusesImpossibleCounts) {
  EXPECT_FALSE(FisherExactTwoSided(-1, 3, 1, 3).has_value());
  EXPECT_FALSE(FisherExactTwoSided(4, 3, 1, 3).has_value());
  EXPECT_FALSE(FisherExactTwoSided(1, 3, 4, 3).has_value());
}

TEST(BootstrapMedianIntervalTest, SameSeedSameIntervalAroundTheMedian) {
  const std::vector<double> values = {5.1, 3.2, 8.8, 4.4, 6.0, 7.3, 2.9, 5.5, 6.6, 4.9};
  const std::optional<Interval> first = BootstrapMedianInterval(values, 0.95, 2000, 3);
  const std::optional<Interval> again = BootstrapMedianInterval(values, 0.95, 2000, 3);
  ASSERT_TRUE(first.has_value() && again.has_value());
  EXPECT_EQ(first->low, again->low);
  EXPECT_EQ(first->high, again->high);
  const double median = *Median(values);
  EXPECT_LE(first->low, median);
  EXPECT_GE(first->high, median);
  EXPECT_LT(first->low, first->high);
  const std::optional<Interval> constant = BootstrapMedianInterval({4.0, 4.0, 4.0});
  ASSERT_TRUE(constant.has_value());
  EXPECT_EQ(constant->low, 4.0);
  EXPECT_EQ(constant->high, 4.0);
}

TEST(BootstrapMedianIntervalTest, CoversTheTrueMedianAboutAsOftenAsItClaims) {
  // 200 samples of 30 uniform values on [0, 1] (true median 0.5): a 95 % interval should miss it
  // in about 10 of them; percentile intervals of a median run a little narrow on small samples.
  Rng rng(11);
  int covered = 0;
  for (int sample = 0; sample < 200; ++sample) {
    std::vector<double> values(30);
    for (double& v : values) v = rng.Uniform();
    const std::optional<Interval> interval =
        BootstrapMedianInterval(values, 0.95, 1000, sample + 1);
    ASSERT_TRUE(interval.has_value());
    covered += interval->low <= 0.5 && 0.5 <= interval->high;
  }
  EXPECT_GE(covered, 176);  // 88 %
  EXPECT_LE(covered, 198);  // 99 %
}

TEST(BootstrapMedianIntervalTest, RefusesBadArguments) {
  EXPECT_FALSE(BootstrapMedianInterval({}).has_value());
  EXPECT_FALSE(BootstrapMedianInterval({1.0}, 1.0).has_value());
  EXPECT_FALSE(BootstrapMedianInterval({1.0}, 0.95, 0).has_value());
}

TEST(FormatPValueTest, MarksSignificantValues) {
  EXPECT_EQ(FormatPValue(0.2092), "p = 0.209");
  EXPECT_EQ(FormatPValue(0.031), "p = 0.031 *");
  EXPECT_EQ(FormatPValue(2.1e-5), "p = 2.1e-05 *");
  EXPECT_EQ(FormatPValue(0.031, /*mark_significant=*/false), "p = 0.031");
}

}  // namespace
}  // namespace swarmplan::bench
