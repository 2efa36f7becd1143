#include "bench/scenario_selection.h"

#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

// `per_bucket` records in each of `buckets` buckets, in order.
Scenario InBucket(int bucket) {
  Scenario s;
  s.bucket = bucket;
  return s;
}

std::vector<Scenario> Buckets(int buckets, int per_bucket) {
  std::vector<Scenario> scenarios;
  for (int b = 0; b < buckets; ++b) {
    for (int i = 0; i < per_bucket; ++i) scenarios.push_back(InBucket(b));
  }
  return scenarios;
}

using Mode = ScenarioSelection::Mode;

TEST(BenchScenarioSelectionTest, OnePerBucketTakesTheMiddleOfEach) {
  EXPECT_EQ(SelectScenarios(Buckets(3, 10), {Mode::kPerBucket, 1}),
            (std::vector<size_t>{5, 15, 25}));
}

TEST(BenchScenarioSelectionTest, SeveralPerBucketSpreadInsideTheBucket) {
  EXPECT_EQ(SelectScenarios(Buckets(2, 10), {Mode::kPerBucket, 2}),
            (std::vector<size_t>{2, 7, 12, 17}));
}

TEST(BenchScenarioSelectionTest, MoreThanABucketHoldsTakesItAll) {
  std::vector<Scenario> scenarios = Buckets(2, 3);
  scenarios.push_back(InBucket(2));  // a short last bucket
  EXPECT_EQ(SelectScenarios(scenarios, {Mode::kPerBucket, 5}),
            (std::vector<size_t>{0, 1, 2, 3, 4, 5, 6}));
}

TEST(BenchScenarioSelectionTest, EvenlyOverTheWholeFile) {
  EXPECT_EQ(SelectScenarios(Buckets(10, 10), {Mode::kEvenly, 4}),
            (std::vector<size_t>{12, 37, 62, 87}));
  EXPECT_EQ(SelectScenarios(Buckets(1, 3), {Mode::kEvenly, 10}), (std::vector<size_t>{0, 1, 2}));
}

TEST(BenchScenarioSelectionTest, AllAndEmpty) {
  EXPECT_EQ(SelectScenarios(Buckets(2, 2), {Mode::kAll, 0}), (std::vector<size_t>{0, 1, 2, 3}));
  EXPECT_TRUE(SelectScenarios({}, {Mode::kPerBucket, 1}).empty());
}

}  // namespace
}  // namespace swarmplan::bench
