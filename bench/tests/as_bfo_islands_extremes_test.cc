#include "bench/papers/as_bfo_islands_extremes.h"

#include <vector>

#include "gtest/gtest.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

TEST(ExtremePermutationTest, EqualExtremesGiveOne) {
  const std::vector<double> a = {30.38, 30.38, 31.0};
  const std::vector<double> b = {30.38, 32.0};
  EXPECT_DOUBLE_EQ(*ExtremePermutationP(a, b, Extreme::kMin), 1.0);
}

// Three zeros against three fives: the minima differ by 5 only when a split puts all zeros or
// all fives in the first sample, 2 of the C(6, 3) = 20 splits.
TEST(ExtremePermutationTest, MatchesTheExactSplitProbability) {
  const std::vector<double> zeros(3, 0.0), fives(3, 5.0);
  const std::optional<double> p = ExtremePermutationP(zeros, fives, Extreme::kMin);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(*p, 0.1, 0.01);
  EXPECT_NEAR(*ExtremePermutationP(zeros, fives, Extreme::kMax), 0.1, 0.01);
}

// Ten against ten: 2 of C(20, 10) = 184756 splits, so only the +1 of the estimate is left.
TEST(ExtremePermutationTest, SeparatedSamplesAreSignificantAndSeeded) {
  std::vector<double> low(10, 30.0), high(10, 31.0);
  low[3] = 29.0;
  high[5] = 35.0;
  const std::optional<double> p = ExtremePermutationP(low, high, Extreme::kMax, 999, 5);
  ASSERT_TRUE(p.has_value());
  EXPECT_LT(*p, 0.05);
  EXPECT_EQ(p, ExtremePermutationP(low, high, Extreme::kMax, 999, 5));
  EXPECT_FALSE(ExtremePermutationP({}, high, Extreme::kMin).has_value());
  EXPECT_FALSE(ExtremePermutationP(low, high, Extreme::kMin, 0).has_value());
}

}  // namespace
}  // namespace swarmplan::bench::as_bfo_islands
