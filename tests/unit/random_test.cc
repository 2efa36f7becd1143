#include "core/random.h"

#include <cmath>

#include "gtest/gtest.h"

namespace swarmplan {
namespace {

TEST(RngTest, SameSeedSameSequence) {
  Rng a(42), b(42);
  for (int i = 0; i < 1000; ++i) {
    ASSERT_EQ(a.Uniform(), b.Uniform());
    ASSERT_EQ(a.Normal(), b.Normal());
    ASSERT_EQ(a.UniformInt(-5, 5), b.UniformInt(-5, 5));
  }
}

TEST(RngTest, KnownFirstDrawsAreFixedByTheEngineAndOurConversion) {
  // mt19937_64's 10000th output for the default seed is fixed by the C++ standard; our
  // conversion on top of it is fixed by this code, so these values hold on every platform.
  std::mt19937_64 reference;
  reference.discard(9999);
  EXPECT_EQ(reference(), 9981545732273789042ULL);
  Rng rng(5489);
  EXPECT_EQ(rng.NextU64(), 14514284786278117030ULL);
  // The conversions: 53 high bits for Uniform, rejection sampling for UniformInt, the polar
  // method for Normal (whose libm calls may differ in the last bits between platforms).
  EXPECT_EQ(rng.Uniform(), 0.2504803406880286);
  EXPECT_EQ(rng.UniformInt(0, 9), 0);
  EXPECT_NEAR(rng.Normal(), -0.5670942549352187, 1e-12);
  EXPECT_NEAR(rng.Normal(), -1.482959173844121, 1e-12);
}

TEST(RngTest, UniformStaysInRangeWithSensibleMean) {
  Rng rng(7);
  double sum = 0;
  for (int i = 0; i < 100000; ++i) {
    const double u = rng.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  EXPECT_NEAR(sum / 100000, 0.5, 0.01);
}

TEST(RngTest, UniformIntCoversInclusiveRange) {
  Rng rng(3);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 30000; ++i) {
    const int64_t v = rng.UniformInt(0, 2);
    ASSERT_GE(v, 0);
    ASSERT_LE(v, 2);
    ++counts[v];
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 500);
}

TEST(RngTest, NormalHasUnitVariance) {
  Rng rng(11);
  double sum = 0, sq = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = rng.Normal();
    sum += x;
    sq += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sq / n, 1.0, 0.02);
}

TEST(RngTest, UnitDirectionIsUnitAndCoversAllOrthants) {
  Rng rng(13);
  int negative_x = 0;
  for (int i = 0; i < 1000; ++i) {
    Eigen::VectorXd d = rng.UnitDirection(3);
    ASSERT_NEAR(d.norm(), 1.0, 1e-12);
    negative_x += d[0] < 0;
  }
  EXPECT_GT(negative_x, 400);
  EXPECT_LT(negative_x, 600);
}

}  // namespace
}  // namespace swarmplan
