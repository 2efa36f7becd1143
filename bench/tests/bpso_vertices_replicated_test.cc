#include "bench/papers/bpso_vertices_replicated.h"

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/strings/string_view.h"
#include "absl/strings/strip.h"
#include "bench/papers/bpso_vertices_tables.h"
#include "bench/papers/bpso_vertices_worlds.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "bench/tests/read_file.h"
#include "core/geometry/obstacle_vertices.h"
#include "core/graph/visibility_graph.h"
#include "core/map/io/map_writers.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"

namespace swarmplan::bench::bpso {
namespace {

std::string WorldName(int vertices) { return absl::StrCat("bpso-vertices-", vertices); }

TEST(BpsoReplicatedWorldsTest, WorldZeroIsTheShippedWorld) {
  for (int vertices : kVertexCounts) {
    absl::StatusOr<ShapeWorld> first = DrawReplicatedBpsoWorld(vertices, 0);
    ASSERT_TRUE(first.ok()) << first.status();
    const std::string shipped = ReadFile(absl::StrCat(
        SWARMPLAN_SOURCE_DIR, "/bench/worlds/bpso-vertices/", WorldFileName(vertices)));
    ASSERT_FALSE(shipped.empty()) << vertices;
    EXPECT_EQ(FormatShapesJson(*first, WorldName(vertices)), shipped) << vertices;
  }
}

// Every drawn world is a different world with D vertices whose straight path is blocked, and
// drawing it again gives the same world.
TEST(BpsoReplicatedWorldsTest, WorldsAreDistinctBlockedAndDeterministic) {
  for (int vertices : kVertexCounts) {
    std::set<std::string> seen;
    for (int index = 0; index < kReplicatedWorlds; ++index) {
      EXPECT_EQ(ReplicatedBpsoWorldSeed(vertices, index),
                ShippedWorldSeed(vertices) + index * kWorldSeedStride);
      absl::StatusOr<ShapeWorld> world = DrawReplicatedBpsoWorld(vertices, index);
      absl::StatusOr<ShapeWorld> again = DrawReplicatedBpsoWorld(vertices, index);
      ASSERT_TRUE(world.ok() && again.ok()) << vertices << " " << index;
      const std::string json = FormatShapesJson(*world, "w");
      EXPECT_EQ(json, FormatShapesJson(*again, "w"));
      EXPECT_TRUE(seen.insert(json).second) << "D = " << vertices << " world " << index;
      EXPECT_EQ(ObstacleVertices(*world, 0.0, 0.01).size(), static_cast<size_t>(vertices));
      EXPECT_TRUE(GrowObstacles(*world, 0.0, 0.01).Blocks(BpsoVerticesStart(), BpsoVerticesGoal()));
    }
  }
}

// The quick report, run once for the tests below.
const std::string& QuickReport() {
  static const std::string* report = [] {
    ExperimentOptions options;
    options.quick = true;
    options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
    absl::StatusOr<std::string> run = RunBpsoVertices(options);
    EXPECT_TRUE(run.ok()) << run.status();
    return new std::string(run.ok() ? *run : "");
  }();
  return *report;
}

// The cells of the column `header` of the first table that has it.
std::vector<std::string> Column(const std::string& report, const std::string& header) {
  std::vector<std::string> cells;
  int column = -1;
  for (absl::string_view line : absl::StrSplit(report, '\n')) {
    if (!absl::StartsWith(line, "|")) {
      if (column >= 0) break;
      continue;
    }
    std::vector<std::string> parts = absl::StrSplit(line.substr(1), " | ");
    for (std::string& part : parts) part = std::string(absl::StripAsciiWhitespace(part));
    if (!parts.empty()) parts.back() = std::string(absl::StripSuffix(parts.back(), "|"));
    for (std::string& part : parts) part = std::string(absl::StripAsciiWhitespace(part));
    if (column < 0) {
      for (size_t i = 0; i < parts.size(); ++i) {
        if (parts[i] == header) column = static_cast<int>(i);
      }
      continue;
    }
    if (absl::StartsWith(line, "|---")) continue;
    if (column < static_cast<int>(parts.size())) cells.push_back(parts[column]);
  }
  return cells;
}

// "A to B" from the smallest and largest cells, as they are written.
std::string CellRange(const std::vector<std::string>& cells) {
  std::string low, high;
  double low_value = 0.0, high_value = 0.0;
  for (const std::string& cell : cells) {
    const double value = std::stod(cell);
    if (low.empty() || value < low_value) {
      low = cell;
      low_value = value;
    }
    if (high.empty() || value > high_value) {
      high = cell;
      high_value = value;
    }
  }
  return absl::StrCat(low, " to ", high);
}

TEST(BpsoReplicatedReportTest, QuickReportHasEverySection) {
  const std::string& report = QuickReport();
  for (const char* text :
       {"## Table 1: swarm size", "N = 2D against N = 1D:", "## Fig. 4: mutation probability",
        "| best probability (lowest median, then mean) |", "## Fig. 5: convergence",
        "| iteration of final best: median [95% CI] |", "## Table 1 and Fig. 5 on 2 worlds per D",
        "| signed-rank p (world medians) |", "## Discussion", "**On the drawn worlds.**",
        "N = 2D against N = 1D on 2 worlds per D", "The claim is"}) {
    EXPECT_NE(report.find(text), std::string::npos) << text;
  }
  EXPECT_EQ(report.find("Numbers quoted here"), std::string::npos);
  for (int vertices : kVertexCounts) {
    for (int index = 0; index < 2; ++index) {
      absl::StatusOr<ShapeWorld> world = DrawReplicatedBpsoWorld(vertices, index);
      ASSERT_TRUE(world.ok());
      absl::StatusOr<Path> path =
          ShortestPathVisibility(*world, BpsoVerticesStart(), BpsoVerticesGoal(), 0.0, 0.01);
      ASSERT_TRUE(path.ok());
      const std::string row = absl::StrCat("| ", vertices, " | ", index == 0 ? "0 (shipped)" : "1",
                                           " | ", ReplicatedBpsoWorldSeed(vertices, index), " | ",
                                           NumberCell(PathLength(*path)), " |");
      EXPECT_NE(report.find(row), std::string::npos) << row;
    }
  }
}

TEST(BpsoReplicatedReportTest, DiscussionQuotesTheTablesRatios) {
  const std::string& report = QuickReport();
  const size_t discussion = report.find("## Discussion");
  ASSERT_NE(discussion, std::string::npos);
  const std::string text = report.substr(discussion);

  const std::vector<std::string> paper_over_ours = Column(report, kPaperOverOurTimeHeader);
  ASSERT_EQ(paper_over_ours.size(), 12u);
  const std::string times =
      absl::StrCat("The paper's times are ", CellRange(paper_over_ours), " times ours");
  EXPECT_NE(text.find(times), std::string::npos) << times;

  const std::vector<std::string> ours_2d_over_1d = Column(report, "ours: median time 2D / 1D");
  const std::vector<std::string> paper_2d_over_1d = Column(report, "paper: time 2D / 1D");
  ASSERT_EQ(ours_2d_over_1d.size(), 4u);
  ASSERT_EQ(paper_2d_over_1d.size(), 4u);
  const std::string ratios = absl::StrCat("Our median time 2D / 1D is ", CellRange(ours_2d_over_1d),
                                          ", the paper's ", CellRange(paper_2d_over_1d));
  EXPECT_NE(text.find(ratios), std::string::npos) << ratios;
}

}  // namespace
}  // namespace swarmplan::bench::bpso
