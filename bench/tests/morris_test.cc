#include "bench/papers/morris.h"

#include <cmath>
#include <set>
#include <vector>

#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

constexpr int kFactors = 4;
constexpr int kLevels = 4;

// y = 2 x0 − 3 x1 + 5 x2 x3: the elementary effects of x0 and x1 are 2 and −3 everywhere, the
// ones of x2 and x3 are 5 x3 and 5 x2 at the point where the factor moves.
double Model(const std::vector<double>& x) { return 2.0 * x[0] - 3.0 * x[1] + 5.0 * x[2] * x[3]; }

std::vector<std::vector<double>> Outputs(const std::vector<MorrisTrajectory>& trajectories) {
  std::vector<std::vector<double>> outputs;
  for (const MorrisTrajectory& t : trajectories) {
    outputs.emplace_back();
    for (const std::vector<double>& x : t.points) outputs.back().push_back(Model(x));
  }
  return outputs;
}

TEST(MorrisTest, TrajectoriesMoveEachFactorOnceByDeltaOnTheGrid) {
  absl::StatusOr<std::vector<MorrisTrajectory>> trajectories =
      MorrisTrajectories(kFactors, kLevels, 20, 7);
  ASSERT_TRUE(trajectories.ok()) << trajectories.status();
  ASSERT_EQ(trajectories->size(), 20u);
  EXPECT_DOUBLE_EQ(MorrisDelta(kLevels), 2.0 / 3.0);
  for (const MorrisTrajectory& t : *trajectories) {
    ASSERT_EQ(t.points.size(), kFactors + 1u);
    EXPECT_EQ(std::set<int>(t.changed.begin(), t.changed.end()).size(), size_t{kFactors});
    for (const std::vector<double>& x : t.points) {
      for (double v : x) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
        const double level = v * (kLevels - 1);
        EXPECT_NEAR(level, std::round(level), 1e-12);
      }
    }
    for (int i = 0; i < kFactors; ++i) {
      for (int f = 0; f < kFactors; ++f) {
        const double step = t.points[i + 1][f] - t.points[i][f];
        if (f == t.changed[i]) {
          EXPECT_NEAR(std::abs(step), MorrisDelta(kLevels), 1e-12);
        } else {
          EXPECT_EQ(step, 0.0);
        }
      }
    }
  }
}

TEST(MorrisTest, SameSeedSameTrajectoriesOtherSeedOthers) {
  const auto a = MorrisTrajectories(kFactors, kLevels, 5, 3);
  const auto b = MorrisTrajectories(kFactors, kLevels, 5, 3);
  const auto c = MorrisTrajectories(kFactors, kLevels, 5, 4);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  bool differs = false;
  for (size_t t = 0; t < a->size(); ++t) {
    EXPECT_EQ((*a)[t].points, (*b)[t].points);
    EXPECT_EQ((*a)[t].changed, (*b)[t].changed);
    differs = differs || (*a)[t].points != (*c)[t].points;
  }
  EXPECT_TRUE(differs);
}

TEST(MorrisTest, RejectsOddLevelsAndEmptyDesigns) {
  EXPECT_FALSE(MorrisTrajectories(kFactors, 3, 4, 1).ok());
  EXPECT_FALSE(MorrisTrajectories(0, kLevels, 4, 1).ok());
  EXPECT_FALSE(MorrisTrajectories(kFactors, kLevels, 0, 1).ok());
}

TEST(MorrisTest, LinearFactorsHaveTheirCoefficientAndTheInteractionItsPartner) {
  const auto trajectories = MorrisTrajectories(kFactors, kLevels, 30, 11);
  ASSERT_TRUE(trajectories.ok());
  absl::StatusOr<MorrisIndices> indices =
      MorrisElementaryEffects(*trajectories, Outputs(*trajectories));
  ASSERT_TRUE(indices.ok()) << indices.status();
  EXPECT_NEAR(indices->mu[0], 2.0, 1e-9);
  EXPECT_NEAR(indices->mu_star[0], 2.0, 1e-9);
  EXPECT_NEAR(indices->sigma[0], 0.0, 1e-9);
  EXPECT_NEAR(indices->mu[1], -3.0, 1e-9);
  EXPECT_NEAR(indices->mu_star[1], 3.0, 1e-9);
  EXPECT_NEAR(indices->sigma[1], 0.0, 1e-9);
  // Each interaction effect is 5 times the partner's value where the factor moves.
  std::vector<double> expected2, expected3;
  for (const MorrisTrajectory& t : *trajectories) {
    for (int i = 0; i < kFactors; ++i) {
      if (t.changed[i] == 2) expected2.push_back(5.0 * t.points[i][3]);
      if (t.changed[i] == 3) expected3.push_back(5.0 * t.points[i][2]);
    }
  }
  ASSERT_EQ(indices->effects[2].size(), expected2.size());
  for (size_t t = 0; t < expected2.size(); ++t) {
    EXPECT_NEAR(indices->effects[2][t], expected2[t], 1e-9);
    EXPECT_NEAR(indices->effects[3][t], expected3[t], 1e-9);
  }
  // The partner sits on several levels, so the interaction shows as σ > 0.
  EXPECT_GT(indices->sigma[2], 0.5);
  EXPECT_GT(indices->sigma[3], 0.5);
  EXPECT_NEAR(indices->mu_star[2], indices->mu[2], 1e-9);  // every effect ≥ 0
}

TEST(MorrisTest, IndicesOfAHandComputedTwoTrajectoryDesign) {
  // Factor 0 moves up by 2/3 then down by 2/3; factor 1 the other way.
  const std::vector<MorrisTrajectory> design = {
      {{{0.0, 1.0}, {2.0 / 3.0, 1.0}, {2.0 / 3.0, 1.0 / 3.0}}, {0, 1}},
      {{{1.0, 0.0}, {1.0, 2.0 / 3.0}, {1.0 / 3.0, 2.0 / 3.0}}, {1, 0}},
  };
  // Effects: factor 0: (3 − 1) / (2/3) = 3 and (4 − 8) / (−2/3) = 6; factor 1:
  // (0 − 3) / (−2/3) = 4.5 and (8 − 10) / (2/3) = −3.
  const std::vector<std::vector<double>> outputs = {{1.0, 3.0, 0.0}, {10.0, 8.0, 4.0}};
  absl::StatusOr<MorrisIndices> indices = MorrisElementaryEffects(design, outputs);
  ASSERT_TRUE(indices.ok()) << indices.status();
  EXPECT_NEAR(indices->mu[0], 4.5, 1e-12);
  EXPECT_NEAR(indices->mu_star[0], 4.5, 1e-12);
  EXPECT_NEAR(indices->sigma[0], std::sqrt(4.5), 1e-12);
  EXPECT_NEAR(indices->mu[1], 0.75, 1e-12);
  EXPECT_NEAR(indices->mu_star[1], 3.75, 1e-12);
  EXPECT_NEAR(indices->sigma[1], std::sqrt(2.0 * 3.75 * 3.75), 1e-12);
  EXPECT_FALSE(MorrisElementaryEffects(design, {{1.0, 3.0, 0.0}}).ok());
}

TEST(MorrisTest, BootstrapIntervalOfMuStarHoldsTheEstimate) {
  const std::optional<MuStarInterval> constant = BootstrapMuStar({-2.0, 2.0, 2.0}, 0.95, 500, 1);
  ASSERT_TRUE(constant.has_value());
  EXPECT_DOUBLE_EQ(constant->low, 2.0);
  EXPECT_DOUBLE_EQ(constant->high, 2.0);
  const std::optional<MuStarInterval> spread = BootstrapMuStar({1.0, 2.0, 3.0, 10.0}, 0.95, 2000);
  ASSERT_TRUE(spread.has_value());
  EXPECT_LE(spread->low, 4.0);
  EXPECT_GE(spread->high, 4.0);
  EXPECT_GE(spread->low, 1.0);
  EXPECT_LE(spread->high, 10.0);
  EXPECT_LT(spread->low, spread->high);
  EXPECT_FALSE(BootstrapMuStar({}).has_value());
}

}  // namespace
}  // namespace swarmplan::bench
