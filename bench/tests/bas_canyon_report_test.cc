// The bas-canyon report in quick mode: the same on one or two threads, every section present,
// and its figures (not its times) pinned by a digest.

#include <string>
#include <vector>

#include "bench/papers/experiments.h"
#include "bench/papers/report_digest.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

// The sections whose figures are wall times.
const std::vector<std::string> kTimedSections = {"## Time"};

absl::StatusOr<std::string> QuickReport(int jobs) {
  ExperimentOptions options;
  options.quick = true;
  options.jobs = jobs;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  return RunBasCanyon(options);
}

TEST(BasCanyonReportTest, SameReportOnOneOrTwoThreads) {
  absl::StatusOr<std::string> one = QuickReport(1);
  absl::StatusOr<std::string> two = QuickReport(2);
  ASSERT_TRUE(one.ok()) << one.status();
  ASSERT_TRUE(two.ok()) << two.status();
  EXPECT_EQ(WithoutSections(*one, kTimedSections), WithoutSections(*two, kTimedSections));
  EXPECT_NE(*one, WithoutSections(*one, kTimedSections));  // the time section exists

  for (const char* text :
       {"## Setup", "## Table A", "## Table B", "## Significance of the paper's claims",
        "## Table C", "## Table D", "| lfs-bas, map steps + reject |", "## Table 3",
        "| aco, 10 iterations |", "## Fig. 6: moved start", "| aco-bas, moved start |",
        "## Replication over 2 canyons", "signed-rank p (world medians)", "## Figs. 10-11: 2D",
        "| bas + PSO term (eq. 19) |", "## Discussion", "## Time per run"}) {
    EXPECT_NE(one->find(text), std::string::npos) << text;
  }
}

// The quick report's figures (not its times) are fixed by the seeds: a change that moves them
// moves the committed tables too, so bench/results/bas-canyon.md must be re-run and this digest
// updated with it.
TEST(BasCanyonReportTest, QuickReportDigestIsPinned) {
  absl::StatusOr<std::string> report = QuickReport(2);
  ASSERT_TRUE(report.ok()) << report.status();
  EXPECT_EQ(ReportDigest(*report, kTimedSections), "a42f14b7ac37cbc9");
}

}  // namespace
}  // namespace swarmplan::bench
