#include <string>
#include <vector>

#include "bench/papers/experiments.h"
#include "bench/papers/report_digest.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

// The section whose figures are wall times.
const std::vector<std::string> kTimedSections = {"## Time"};

absl::StatusOr<std::string> QuickReport() {
  ExperimentOptions options;
  options.quick = true;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  return RunIdafsaGrids(options);
}

TEST(IdafsaGridsReportTest, HasTheMovesAblationAndKeepsTimesApart) {
  absl::StatusOr<std::string> report = QuickReport();
  ASSERT_TRUE(report.ok()) << report.status();
  for (const char* text :
       {"| fish moves |", "## The earlier random-closer moves",
        "idafsa, random-closer moves (earlier default)", "idafsa, no prey culling",
        "| 10 x 10, shipped world | Shorter paths | dafsa |",
        "| 20 x 20, across drawn worlds | Higher success | afsa-4 |",
        "- **Do the paper's moves change the verdicts?**", "## Time per run"}) {
    EXPECT_NE(report->find(text), std::string::npos) << text;
  }
  const std::string untimed = WithoutSections(*report, kTimedSections);
  EXPECT_EQ(untimed.find("(ms)"), std::string::npos);
  EXPECT_NE(report->find("(ms)"), std::string::npos);
}

// The quick report's figures (not its times) are fixed by the seeds: a change that moves them
// moves the committed tables too, so bench/results/idafsa-grids.md must be re-run and this
// digest updated with it.
TEST(IdafsaGridsReportTest, QuickReportDigestIsPinned) {
  absl::StatusOr<std::string> report = QuickReport();
  ASSERT_TRUE(report.ok()) << report.status();
  EXPECT_EQ(ReportDigest(*report, kTimedSections), "8b6dfee86026815a");
}

}  // namespace
}  // namespace swarmplan::bench
