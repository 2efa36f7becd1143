#include "bench/papers/report_stamp.h"

#include <filesystem>
#include <regex>
#include <string>

#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

TEST(ReportStampTest, NamesTheCommandTheCommitAndTheBuild) {
  const std::string stamp =
      ReportStamp("swarmplan-papers run aem-bso-worlds", SWARMPLAN_SOURCE_DIR, "Release");
  EXPECT_NE(stamp.find("`swarmplan-papers run aem-bso-worlds`"), std::string::npos) << stamp;
  EXPECT_NE(stamp.find("Release build"), std::string::npos) << stamp;
  if (std::filesystem::exists(std::filesystem::path(SWARMPLAN_SOURCE_DIR) / ".git")) {
    EXPECT_TRUE(std::regex_search(stamp, std::regex("commit `[0-9a-f]{12}`"))) << stamp;
  }
}

TEST(ReportStampTest, OutsideACheckoutTheCommitIsUnknown) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "swarmplan-report-stamp-test";
  std::filesystem::create_directories(dir);
  const std::string stamp = ReportStamp("x", dir.string(), "Debug");
  std::filesystem::remove_all(dir);
  EXPECT_NE(stamp.find("an unknown commit"), std::string::npos) << stamp;
  EXPECT_NE(stamp.find("Debug build"), std::string::npos) << stamp;
}

TEST(ReportStampTest, GoesUnderTheTitle) {
  EXPECT_EQ(InsertStamp("# Title\n\nText.\n", "*stamp*\n"), "# Title\n\n*stamp*\n\nText.\n");
  EXPECT_EQ(InsertStamp("Text.\n", "*stamp*\n"), "*stamp*\n\nText.\n");
}

}  // namespace
}  // namespace swarmplan::bench
