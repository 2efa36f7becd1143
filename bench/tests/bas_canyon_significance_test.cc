// The bas-canyon comparisons on hand-made runs: the verdicts follow the tests' direction.

#include "bench/papers/bas_canyon_significance.h"

#include <string>
#include <vector>

#include "bench/papers/bas_canyon_sweeps.h"
#include "gtest/gtest.h"

namespace swarmplan::bench::bas {
namespace {

RowRuns Runs(std::vector<double> fitness, int runs, int right_branch = 0) {
  RowRuns out;
  out.runs = runs;
  out.fitness = std::move(fitness);
  out.right_branch = right_branch;
  return out;
}

RowSet TwoRows(const std::string& first, RowRuns a, const std::string& second, RowRuns b) {
  RowSet set;
  set.rows = {{first, {}}, {second, {}}};
  set.runs = {std::move(a), std::move(b)};
  return set;
}

std::vector<double> Range(double from, int count) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) out.push_back(from + i);
  return out;
}

TEST(BasCanyonSignificanceTest, LowerOtherIsSupportedHigherContradicted) {
  // Ten runs each, disjoint: the exact two-sided rank-sum p is 2 / C(20, 10) = 1.08e-5.
  const RowSet set = TwoRows("aco", Runs(Range(100, 10), 10), "lfs-bas", Runs(Range(50, 10), 10));
  const std::vector<PairTest> lower = TestPairs(set, {{"aco", "lfs-bas", "claim"}});
  ASSERT_EQ(lower.size(), 1u);
  EXPECT_TRUE(lower[0].supported());
  EXPECT_FALSE(lower[0].contradicted());
  EXPECT_NEAR(*lower[0].fitness.p, 2.0 / 184756.0, 1e-9);
  EXPECT_EQ(Verdict(lower[0]), "supported");
  const std::vector<PairTest> higher = TestPairs(set, {{"lfs-bas", "aco", "claim"}});
  EXPECT_TRUE(higher[0].contradicted());
  EXPECT_EQ(Verdict(higher[0]), "contradicted");
  // An unknown row is skipped.
  EXPECT_TRUE(TestPairs(set, {{"aco", "bas", "claim"}}).empty());
}

TEST(BasCanyonSignificanceTest, OverlappingRunsAreNotSignificant) {
  const RowSet set = TwoRows("a", Runs({1, 3, 5, 7}, 4), "b", Runs({2, 4, 6, 8}, 4));
  const std::vector<PairTest> tests = TestPairs(set, {{"a", "b", "claim"}});
  ASSERT_EQ(tests.size(), 1u);
  EXPECT_EQ(Verdict(tests[0]), "not significant");
  EXPECT_FALSE(Significant(tests[0].found_p));
}

TEST(BasCanyonSignificanceTest, MovedStartComparesTheDeepBranchCounts) {
  RowSet set = TwoRows("lfs-bas, moved start", Runs(Range(90, 10), 10, 10), "aco-bas, moved start",
                       Runs(Range(120, 10), 10, 0));
  const MovedStartTest test = TestMovedStart(set);
  EXPECT_EQ(test.lfs_right.successes, 10);
  EXPECT_EQ(test.aco_bas_right.successes, 0);
  // Fisher's exact two-sided p of 10/10 against 0/10: 2 / C(20, 10).
  EXPECT_NEAR(*test.p, 2.0 / 184756.0, 1e-9);
  EXPECT_TRUE(test.supported());
  set.runs[0].right_branch = 0;
  EXPECT_FALSE(TestMovedStart(set).supported());
}

}  // namespace
}  // namespace swarmplan::bench::bas
