#include "bench/papers/report_stamp.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
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

// A change to a report does not make the next report's tree "uncommitted"; a change to a
// source does.
TEST(ReportStampTest, ChangedReportsAreNotUncommittedChanges) {
  if (std::system("git --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no git";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "swarmplan-report-stamp-git-test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / kReportsDir);
  auto write = [&](const std::string& file, const std::string& text) {
    std::ofstream(dir / file) << text;
  };
  write("source.cc", "int x;\n");
  write(std::string(kReportsDir) + "/report.md", "# Report\n");
  const std::string git = "git -C '" + dir.string() + "' ";
  ASSERT_EQ(std::system((git + "init -q && " + git + "add -A && " + git +
                         "-c user.name=t -c user.email=t@t commit -qm x")
                            .c_str()),
            0);
  EXPECT_EQ(ReportStamp("x", dir.string(), "Release").find("uncommitted"), std::string::npos);
  write(std::string(kReportsDir) + "/report.md", "# Report, re-run\n");
  EXPECT_EQ(ReportStamp("x", dir.string(), "Release").find("uncommitted"), std::string::npos);
  write("source.cc", "int y;\n");
  EXPECT_NE(ReportStamp("x", dir.string(), "Release").find("with uncommitted changes"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ReportStampTest, GoesUnderTheTitle) {
  EXPECT_EQ(InsertStamp("# Title\n\nText.\n", "*stamp*\n"), "# Title\n\n*stamp*\n\nText.\n");
  EXPECT_EQ(InsertStamp("Text.\n", "*stamp*\n"), "*stamp*\n\nText.\n");
}

}  // namespace
}  // namespace swarmplan::bench
