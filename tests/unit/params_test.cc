#include "core/params.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

std::vector<ParamSpec> Schema() {
  return {
      ParamSpec::Int("population", 50, 1, 10000, "", "swarm size"),
      ParamSpec::Double("step", 0.5, 0.0, 10.0, "cells", "step length"),
      ParamSpec::Bool("mutation", true, "elite mutation on"),
      ParamSpec::Enum("interpolation", "spline", {"spline", "linear", "nearest"}, "path shape"),
  };
}

TEST(ParamSetTest, FillsDefaults) {
  absl::StatusOr<ParamSet> set = ParamSet::Resolve(Schema(), {});
  ASSERT_TRUE(set.ok()) << set.status();
  EXPECT_EQ(set->Int("population"), 50);
  EXPECT_EQ(set->Double("step"), 0.5);
  EXPECT_TRUE(set->Bool("mutation"));
  EXPECT_EQ(set->Enum("interpolation"), "spline");
}

TEST(ParamSetTest, AcceptsGivenValuesAndWidensIntToDouble) {
  absl::StatusOr<ParamSet> set = ParamSet::Resolve(
      Schema(), {{"population", int64_t{7}}, {"step", int64_t{2}}, {"interpolation", "linear"}});
  ASSERT_TRUE(set.ok()) << set.status();
  EXPECT_EQ(set->Int("population"), 7);
  EXPECT_EQ(set->Double("step"), 2.0);
  EXPECT_EQ(set->Enum("interpolation"), "linear");
}

TEST(ParamSetTest, AcceptsIntegralDoubleForInt) {
  absl::StatusOr<ParamSet> set = ParamSet::Resolve(Schema(), {{"population", 12.0}});
  ASSERT_TRUE(set.ok()) << set.status();
  EXPECT_EQ(set->Int("population"), 12);
}

TEST(ParamSetTest, RejectsUnknownNameListingValidOnes) {
  absl::StatusOr<ParamSet> set = ParamSet::Resolve(Schema(), {{"popsize", int64_t{3}}});
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(set.status().message(), HasSubstr("unknown parameter 'popsize'"));
  EXPECT_THAT(set.status().message(), HasSubstr("population"));
}

TEST(ParamSetTest, RejectsWrongTypeNamingParameter) {
  absl::StatusOr<ParamSet> set = ParamSet::Resolve(Schema(), {{"mutation", int64_t{1}}});
  ASSERT_FALSE(set.ok());
  EXPECT_THAT(set.status().message(), HasSubstr("parameter 'mutation': expected bool"));
  set = ParamSet::Resolve(Schema(), {{"population", 2.5}});
  ASSERT_FALSE(set.ok());
  EXPECT_THAT(set.status().message(), HasSubstr("parameter 'population': expected int"));
}

TEST(ParamSetTest, RejectsOutOfRangeWithRange) {
  absl::StatusOr<ParamSet> set = ParamSet::Resolve(Schema(), {{"step", 11.0}});
  ASSERT_FALSE(set.ok());
  EXPECT_THAT(set.status().message(), HasSubstr("parameter 'step'"));
  EXPECT_THAT(set.status().message(), HasSubstr("out of range [0, 10] cells"));
  set = ParamSet::Resolve(Schema(), {{"population", int64_t{0}}});
  ASSERT_FALSE(set.ok());
  EXPECT_THAT(set.status().message(), HasSubstr("parameter 'population'"));
}

TEST(ParamSetTest, RejectsNonFiniteAndUnknownChoice) {
  absl::StatusOr<ParamSet> set =
      ParamSet::Resolve(Schema(), {{"step", std::numeric_limits<double>::quiet_NaN()}});
  ASSERT_FALSE(set.ok());
  EXPECT_THAT(set.status().message(), HasSubstr("finite"));
  set = ParamSet::Resolve(Schema(), {{"interpolation", "cubic"}});
  ASSERT_FALSE(set.ok());
  EXPECT_THAT(set.status().message(), HasSubstr("'cubic' is not one of spline, linear, nearest"));
}

}  // namespace
}  // namespace swarmplan
