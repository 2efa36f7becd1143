#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/papers/experiment.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/plan_once.h"
#include "bench/tests/read_file.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

namespace fs = std::filesystem;

TEST(MarkdownTableTest, AlignsNumberColumnsRightAndPadsShortRows) {
  MarkdownTable table({"planner", "best", "mean"});
  table.AddRow({"bso", "1.5", "2.5"});
  table.AddRow({"pso", "3"});
  EXPECT_EQ(table.ToString(),
            "| planner | best | mean |\n"
            "|---|---:|---:|\n"
            "| bso | 1.5 | 2.5 |\n"
            "| pso | 3 |  |\n");
}

TEST(MarkdownTableTest, NumberCellsKeepSignificantDigits) {
  EXPECT_EQ(NumberCell(134.5678), "134.6");
  EXPECT_EQ(NumberCell(12345.6), "12346");
  EXPECT_EQ(NumberCell(0.5), "0.5000");
  EXPECT_EQ(NumberCell(0.0), "0.000");
  EXPECT_EQ(NumberCell(2.5e-7), "2.500e-07");
  EXPECT_EQ(NumberCell(std::nullopt), "–");
  EXPECT_EQ(PercentCell(0.95), "95%");
}

TEST(CheckFoundPathTest, AcceptsNoPathAndValidPathsRejectsCollisionsAndWrongEnds) {
  const Point3 start(1, 1, 0), goal(5, 1, 0);
  PlanResult result;
  result.found = false;
  EXPECT_TRUE(CheckFoundPath(result, start, goal, "none").ok());

  result.found = true;
  result.raw_path = {start, Point3(3, 2, 0), goal};
  result.raw_metrics.collision_free = true;
  EXPECT_TRUE(CheckFoundPath(result, start, goal, "ok").ok());

  result.raw_metrics.collision_free = false;
  const absl::Status collision = CheckFoundPath(result, start, goal, "bso seed 3");
  EXPECT_EQ(collision.code(), absl::StatusCode::kInternal);
  EXPECT_NE(collision.message().find("bso seed 3: the found path is not collision-free"),
            std::string::npos);

  result.raw_metrics.collision_free = true;
  result.raw_path.back() = Point3(5, 1.001, 0);
  EXPECT_EQ(CheckFoundPath(result, start, goal, "ends").code(), absl::StatusCode::kInternal);
  EXPECT_TRUE(CheckFoundPath(result, start, goal, "loose", 0.01).ok());
  result.raw_path = {start};
  EXPECT_EQ(CheckFoundPath(result, start, goal, "short").code(), absl::StatusCode::kInternal);
}

TEST(PapersTest, ExperimentNamesAreUniqueAndFindable) {
  for (const Experiment& experiment : Experiments()) {
    EXPECT_EQ(FindExperiment(experiment.name), &experiment);
    EXPECT_FALSE(experiment.results_file.empty()) << experiment.name;
  }
  EXPECT_EQ(FindExperiment("no-such-experiment"), nullptr);
}

class ExperimentTest : public testing::TestWithParam<Experiment> {};

// The shipped worlds are exactly what the seeded generator writes, so anybody can recreate them.
TEST_P(ExperimentTest, ShippedWorldsAreWhatTheGeneratorWrites) {
  const Experiment& experiment = GetParam();
  if (!experiment.generate) GTEST_SKIP() << experiment.name << " uses no generated worlds";
  const fs::path generated =
      fs::temp_directory_path() /
      ("swarmplan-papers-test-" + experiment.name + "-" + std::to_string(::getpid()));
  fs::create_directories(generated);
  ASSERT_TRUE(experiment.generate(generated.string()).ok());
  const fs::path shipped = fs::path(SWARMPLAN_SOURCE_DIR) / "bench/worlds" / experiment.name;
  int files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(generated)) {
    ++files;
    const fs::path shipped_file = shipped / entry.path().filename();
    ASSERT_TRUE(fs::exists(shipped_file)) << shipped_file << " is not shipped";
    EXPECT_EQ(ReadFile(entry.path()), ReadFile(shipped_file)) << shipped_file << " differs";
  }
  EXPECT_GT(files, 0);
  fs::remove_all(generated);
}

// Quick mode runs every configuration of the report briefly; the experiment itself fails when a
// planner returns an invalid path.
TEST_P(ExperimentTest, QuickRunProducesAReport) {
  const Experiment& experiment = GetParam();
  ExperimentOptions options;
  options.quick = true;
  options.seed = 1;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  absl::StatusOr<std::string> report = experiment.run(options);
  ASSERT_TRUE(report.ok()) << report.status();
  EXPECT_NE(report->find("|---"), std::string::npos) << "no table in the report";
}

INSTANTIATE_TEST_SUITE_P(Papers, ExperimentTest, testing::ValuesIn(Experiments()),
                         [](const testing::TestParamInfo<Experiment>& info) {
                           std::string name = info.param.name;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace swarmplan::bench
