#include "bench/papers/as_bfo_islands_report.h"

#include <string>
#include <vector>

#include "bench/papers/as_bfo_islands_morris.h"
#include "bench/papers/as_bfo_islands_times.h"
#include "bench/papers/experiments.h"
#include "bench/papers/report_digest.h"
#include "gtest/gtest.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

// The section whose figures are wall times.
const std::vector<std::string> kTimedSections = {kTimesHeading};

absl::StatusOr<std::string> QuickReport(int jobs) {
  ExperimentOptions options;
  options.quick = true;
  options.jobs = jobs;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  return RunAsBfoIslands(options);
}

// The text of the section that starts with `heading`, up to the next "## ".
std::string Section(const std::string& report, const std::string& heading) {
  const size_t start = report.find(heading);
  if (start == std::string::npos) return "";
  const size_t end = report.find("\n## ", start + heading.size());
  return report.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

class AsBfoIslandsReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    absl::StatusOr<std::string> one = QuickReport(1);
    absl::StatusOr<std::string> two = QuickReport(2);
    ASSERT_TRUE(one.ok()) << one.status();
    ASSERT_TRUE(two.ok()) << two.status();
    one_ = new std::string(*std::move(one));
    two_ = new std::string(*std::move(two));
  }
  static void TearDownTestSuite() {
    delete one_;
    delete two_;
    one_ = two_ = nullptr;
  }
  static std::string* one_;
  static std::string* two_;
};
std::string* AsBfoIslandsReportTest::one_ = nullptr;
std::string* AsBfoIslandsReportTest::two_ = nullptr;

TEST_F(AsBfoIslandsReportTest, SameReportOnOneOrTwoThreads) {
  ASSERT_NE(one_, nullptr);
  EXPECT_EQ(WithoutSections(*one_, kTimedSections), WithoutSections(*two_, kTimedSections));
}

// Table 4's main rows start from wandering initial paths; the near-A* ones are the ablation.
TEST_F(AsBfoIslandsReportTest, MainRowsWanderAndTheNearAStarRowsAreTheAblation) {
  ASSERT_NE(one_, nullptr);
  EXPECT_EQ(Methods()[0].label, "AS-BFO");
  EXPECT_EQ(std::get<int64_t>(Methods()[0].params.at("max_waypoints")), kWanderingVia);
  EXPECT_EQ(std::get<int64_t>(Methods()[2].params.at("max_waypoints")), kWanderingVia);
  for (const Method& m : Methods()) {
    if (m.paper_row < 0) {
      EXPECT_EQ(m.params.count("max_waypoints"), 0u) << m.label;
    }
  }
  for (const char* text : {"| ablation rows |", "| AIN | AS-BFO near-A* |", "| AIN | GA near-A* |",
                           "| initial paths |"}) {
    EXPECT_NE(one_->find(text), std::string::npos) << text;
  }
}

// Every wall time is in the run-time section, so the rest of the report is deterministic.
TEST_F(AsBfoIslandsReportTest, WallTimesOnlyInTheRunTimeSection) {
  ASSERT_NE(one_, nullptr);
  const std::string rest = WithoutSections(*one_, kTimedSections);
  EXPECT_EQ(rest.find("time ms"), std::string::npos);
  EXPECT_EQ(rest.find("run time"), std::string::npos);
  EXPECT_NE(Section(*one_, kTimesHeading).find("| time ms (mean) | ACO |"), std::string::npos);
}

TEST_F(AsBfoIslandsReportTest, HasTheMorrisAnalysisAndTheTestsOfTheExtremes) {
  ASSERT_NE(one_, nullptr);
  const std::string morris = Section(*one_, "## Section 4.2: Morris sensitivity analysis");
  ASSERT_FALSE(morris.empty());
  // The paper's Table 1 ranges on a 4-level grid.
  for (const char* text : {"P ∈ (10, 100): 10, 40, 70, 100", "Nc ∈ (2, 12): 2, 5, 9, 12",
                           "Nre ∈ (1, 8): 1, 3, 6, 8", "Ned ∈ (1, 10): 1, 4, 7, 10",
                           "| env1 S1 10×10 | APL | Nre |", "| env2 S1 10×10 | AIN | Ned |"}) {
    EXPECT_NE(morris.find(text), std::string::npos) << text;
  }
  EXPECT_NE(one_->find("**Section 4.2, the Morris analysis.**"), std::string::npos);
  EXPECT_NE(one_->find("| MinPL / MaxPL | permutation min | permutation max |"), std::string::npos);
  EXPECT_NE(one_->find("by the permutation test of the minima"), std::string::npos);
}

// The quick report's figures (not its times) are fixed by the seeds: a change that moves them
// moves the committed tables too, so bench/results/as-bfo-islands.md must be re-run and this
// digest updated with it.
TEST_F(AsBfoIslandsReportTest, QuickReportDigestIsPinned) {
  ASSERT_NE(one_, nullptr);
  EXPECT_EQ(ReportDigest(*one_, kTimedSections), "15009e74f5879929");
}

}  // namespace
}  // namespace swarmplan::bench::as_bfo_islands
