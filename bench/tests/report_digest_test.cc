#include "bench/papers/report_digest.h"

#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

constexpr char kReport[] =
    "# Title\n\nintro\n\n## Table\n\n| a |\n\n## Time per run\n\n12.3 ms\n\n## Discussion\n\nx\n";

TEST(ReportDigestTest, SkipsTheNamedSectionsOnly) {
  EXPECT_EQ(WithoutSections(kReport, {"## Time"}),
            "# Title\n\nintro\n\n## Table\n\n| a |\n\n## Discussion\n\nx\n\n");
  EXPECT_EQ(WithoutSections(kReport, {}), std::string(kReport) + "\n");
}

TEST(ReportDigestTest, IgnoresSkippedSectionsAndSeesEveryOtherCharacter) {
  std::string other_times = kReport;
  other_times.replace(other_times.find("12.3"), 4, "45.6");
  EXPECT_EQ(ReportDigest(kReport, {"## Time"}), ReportDigest(other_times, {"## Time"}));
  EXPECT_NE(ReportDigest(kReport, {}), ReportDigest(other_times, {}));
  std::string other_table = kReport;
  other_table.replace(other_table.find("| a |"), 5, "| b |");
  EXPECT_NE(ReportDigest(kReport, {"## Time"}), ReportDigest(other_table, {"## Time"}));
  EXPECT_EQ(ReportDigest(kReport, {}).size(), 16u);
  // FNV-1a of the empty report "" plus the newline WithoutSections appends.
  EXPECT_EQ(ReportDigest("", {}), "af63c74c8601c8dd");
}

TEST(ReportDigestTest, BlanksTheTimeColumnsOfEveryTable) {
  const std::string report =
      "text with time 1.2\n\n| planner | s/run | length | mean time (s) |\n|---|---:|---:|---:|\n"
      "| a | 0.5 | 10 | 0.7 |\n| b | 0.6 | 11 | 0.8 |\n\n| time |\n|---|\n| 3 |\n";
  EXPECT_EQ(
      WithoutTimeColumns(report),
      "text with time 1.2\n\n| planner | s/run | length | mean time (s) |\n|---|---:|---:|---:|\n"
      "| a | | 10 | |\n| b | | 11 | |\n\n| time |\n|---|\n| |\n\n");
}

}  // namespace
}  // namespace swarmplan::bench
