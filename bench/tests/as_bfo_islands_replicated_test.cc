#include "bench/papers/as_bfo_islands_replicated.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "bench/tests/read_file.h"
#include "core/graph/grid_search.h"
#include "core/map/io/map_writers.h"
#include "gtest/gtest.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

TEST(AsBfoReplicatedWorldsTest, WorldZeroIsTheShippedWorld) {
  for (const IslandEnvironmentSpec& spec : AsBfoEnvironments()) {
    absl::StatusOr<DrawnIslandWorld> drawn = DrawReplicatedIslands(spec, 0, AsBfoSizes());
    ASSERT_TRUE(drawn.ok()) << drawn.status();
    EXPECT_EQ(drawn->first_seed, spec.seed);
    ASSERT_EQ(drawn->grids.size(), AsBfoSizes().size());
    for (size_t s = 0; s < AsBfoSizes().size(); ++s) {
      const std::string path = absl::StrCat(SWARMPLAN_SOURCE_DIR, "/bench/worlds/", kName, "/",
                                            IslandWorldFile(spec.name, AsBfoSizes()[s]));
      EXPECT_EQ(FormatAsciiMap(drawn->grids[s]), ReadFile(path)) << path;
    }
  }
}

// Every drawn world is a different island world of its environment whose corners are joined but
// not by the straight diagonal, and drawing it again gives the same world.
TEST(AsBfoReplicatedWorldsTest, WorldsAreDistinctConnectedAndDeterministic) {
  const std::vector<int> sizes{AsBfoSizes().front(), AsBfoSizes().back()};
  for (const IslandEnvironmentSpec& spec : AsBfoEnvironments()) {
    std::set<std::string> seen;
    for (int index = 0; index < kReplicatedWorlds; ++index) {
      absl::StatusOr<DrawnIslandWorld> world = DrawReplicatedIslands(spec, index, sizes);
      absl::StatusOr<DrawnIslandWorld> again = DrawReplicatedIslands(spec, index, sizes);
      ASSERT_TRUE(world.ok() && again.ok()) << spec.name << " " << index;
      EXPECT_EQ(world->first_seed, spec.seed + index * kWorldSeedStride);
      EXPECT_GE(world->seed_drawn, world->first_seed);
      EXPECT_LT(world->seed_drawn, world->first_seed + kWorldSeedStride);
      EXPECT_EQ(world->seed_drawn, again->seed_drawn);
      for (size_t s = 0; s < sizes.size(); ++s) {
        const OccupancyGrid& grid = world->grids[s];
        EXPECT_EQ(FormatAsciiMap(grid), FormatAsciiMap(again->grids[s]));
        EXPECT_EQ(grid.BlockedCount(), std::lround(spec.obstacle_ratio * sizes[s] * sizes[s]));
        const GridSearchResult path = SearchGrid(grid, IslandStart(sizes[s]), IslandGoal(sizes[s]));
        ASSERT_TRUE(path.found) << spec.name << " " << index;
        EXPECT_GT(path.length, (sizes[s] - 1) * std::sqrt(2.0));
      }
      EXPECT_TRUE(seen.insert(FormatAsciiMap(world->grids.back())).second)
          << spec.name << " world " << index << " repeats";
    }
  }
}

// The numbers of a report's table row, e.g. "| time ms (mean) | ACO |": the first number of each
// cell after the label columns ("1.0 (1.2)" gives 1.0).
std::vector<std::vector<double>> RowNumbers(const std::string& report, const std::string& prefix) {
  std::vector<std::vector<double>> rows;
  for (absl::string_view line : absl::StrSplit(report, '\n')) {
    if (!absl::ConsumePrefix(&line, prefix)) continue;
    std::vector<double> numbers;
    for (absl::string_view cell : absl::StrSplit(line, '|', absl::SkipWhitespace())) {
      const std::vector<std::string> words = absl::StrSplit(cell, ' ', absl::SkipWhitespace());
      double value = 0.0;
      if (!words.empty() && absl::SimpleAtod(words.front(), &value)) numbers.push_back(value);
    }
    rows.push_back(numbers);
  }
  return rows;
}

// The text between `before` and the next `after` in `report`.
std::string Between(const std::string& report, const std::string& before,
                    const std::string& after) {
  const size_t start = report.find(before);
  if (start == std::string::npos) return "";
  const size_t from = start + before.size();
  const size_t end = report.find(after, from);
  return end == std::string::npos ? "" : report.substr(from, end - from);
}

class AsBfoQuickReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ExperimentOptions options;
    options.quick = true;
    options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
    absl::StatusOr<std::string> run = RunAsBfoIslands(options);
    ASSERT_TRUE(run.ok()) << run.status();
    report_ = new std::string(*std::move(run));
  }
  static void TearDownTestSuite() {
    delete report_;
    report_ = nullptr;
  }
  static std::string* report_;
};
std::string* AsBfoQuickReportTest::report_ = nullptr;

TEST_F(AsBfoQuickReportTest, HasTheTestsTheDrawnWorldsAndAComputedDiscussion) {
  ASSERT_NE(report_, nullptr);
  for (const char* text :
       {"## Table 4: tests against AS-BFO", "## Table 4 on 2 worlds per environment",
        "### Tests: smallest against largest value", "## Discussion", "| signed-rank |",
        "**On 2 drawn worlds per environment**", "**The paper's Table 4 claims, tested**"}) {
    EXPECT_NE(report_->find(text), std::string::npos) << text;
  }
  EXPECT_EQ(report_->find("refers to the full run"), std::string::npos);
  for (const IslandEnvironmentSpec& spec : AsBfoEnvironments()) {
    for (int index = 0; index < 2; ++index) {
      const std::string row =
          absl::StrCat("| ", spec.name, " | S1 10×10 | ", index == 0 ? "0 (shipped)" : "1", " | ",
                       ReplicatedWorldSeed(spec.seed, index), " |");
      EXPECT_NE(report_->find(row), std::string::npos) << row;
    }
  }
}

// The ratio range the discussion prints is the one of the time rows of the same report.
TEST_F(AsBfoQuickReportTest, TimeRatioRangeIsTheTimeRowsRatioRange) {
  ASSERT_NE(report_, nullptr);
  const std::vector<std::vector<double>> reference =
      RowNumbers(*report_, "| time ms (mean) | AS-BFO |");
  const std::vector<std::vector<double>> aco = RowNumbers(*report_, "| time ms (mean) | ACO |");
  ASSERT_EQ(reference.size(), 2u);
  ASSERT_EQ(aco.size(), 2u);
  std::vector<double> ratios;
  for (size_t e = 0; e < reference.size(); ++e) {
    ASSERT_EQ(reference[e].size(), aco[e].size());
    for (size_t s = 0; s < reference[e].size(); ++s) ratios.push_back(aco[e][s] / reference[e][s]);
  }
  const std::string printed = Between(*report_, "ACO's mean run time is ", "× AS-BFO's");
  ASSERT_FALSE(printed.empty());
  const std::vector<std::string> ends = absl::StrSplit(printed, "–");
  double low = 0.0, high = 0.0;
  ASSERT_TRUE(absl::SimpleAtod(ends.front(), &low)) << printed;
  ASSERT_TRUE(absl::SimpleAtod(ends.back(), &high)) << printed;
  // Both are rounded to three significant digits: the time cells and the ratios.
  const double low_expected = *std::min_element(ratios.begin(), ratios.end());
  const double high_expected = *std::max_element(ratios.begin(), ratios.end());
  EXPECT_NEAR(low, low_expected, 0.015 * low_expected) << printed;
  EXPECT_NEAR(high, high_expected, 0.015 * high_expected) << printed;
}

// The AIN range the discussion prints is the one of AS-BFO's AIN row.
TEST_F(AsBfoQuickReportTest, AinRangeIsTheAinRowsRange) {
  ASSERT_NE(report_, nullptr);
  std::vector<double> ains;
  for (const std::vector<double>& row : RowNumbers(*report_, "| AIN | AS-BFO |")) {
    ains.insert(ains.end(), row.begin(), row.end());
  }
  ASSERT_FALSE(ains.empty());
  const std::string low = NumberCell(*std::min_element(ains.begin(), ains.end()), 2);
  const std::string high = NumberCell(*std::max_element(ains.begin(), ains.end()), 2);
  const std::string expected = low == high ? low : absl::StrCat(low, "–", high);
  EXPECT_EQ(Between(*report_, "Its AIN in Table 4 is ", " with the wandering"), expected);
}

}  // namespace
}  // namespace swarmplan::bench::as_bfo_islands
