#include <cmath>
#include <string>

#include "core/map/io/map_io.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

constexpr char kSmallMap[] =
    "type octile\n"
    "height 3\n"
    "width 4\n"
    "map\n"
    ".T@.\n"
    "GS.W\n"
    "....\n";

absl::StatusOr<Map> ParseMovingAi(const std::string& bytes, const MapLimits& limits = {}) {
  LoadOptions options;
  options.limits = limits;
  return ParseMap("movingai", {MapFile{"small.map", bytes}}, options);
}

TEST(MapIoMovingAiTest, ParsesCellsWithRowZeroAsYZero) {
  auto map = ParseMovingAi(kSmallMap);
  ASSERT_TRUE(map.ok()) << map.status();
  const OccupancyGrid* grid = map->grid();
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->width(), 4);
  EXPECT_EQ(grid->height(), 3);
  EXPECT_EQ(grid->resolution(), 1.0);
  EXPECT_EQ(grid->origin(), Point2::Zero());
  EXPECT_EQ(grid->value(0, 0), 0);
  EXPECT_EQ(grid->value(1, 0), 100);  // T
  EXPECT_EQ(grid->value(2, 0), 100);  // @
  EXPECT_EQ(grid->value(0, 1), 0);    // G
  EXPECT_EQ(grid->value(1, 1), 0);    // S
  EXPECT_EQ(grid->value(3, 1), 100);  // W
  EXPECT_EQ(grid->BlockedCount(), 3);
}

TEST(MapIoMovingAiTest, AcceptsCrlfAndMissingFinalNewline) {
  std::string crlf;
  for (char c : std::string(kSmallMap)) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  crlf.resize(crlf.size() - 2);  // no newline after the last row
  auto map = ParseMovingAi(crlf);
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(map->grid()->width(), 4);
  EXPECT_EQ(map->grid()->value(3, 2), 0);
}

TEST(MapIoMovingAiTest, RejectsBadHeaders) {
  struct Case {
    std::string bytes;
    std::string message;
  };
  const Case cases[] = {
      {"", "small.map:1: expected 'type octile'"},
      {"type tile\nheight 1\nwidth 1\nmap\n.\n", "small.map:1: expected 'type octile'"},
      {"type octile\nheight x\nwidth 1\nmap\n.\n", "small.map:2: expected 'height N'"},
      {"type octile\nheight 1\nwidth -3\nmap\n.\n", "small.map:3: expected 'width N'"},
      {"type octile\nwidth 1\nheight 1\nmap\n.\n", "small.map:2: expected 'height N'"},
      {"type octile\nheight 1\nwidth 1\ngrid\n.\n", "small.map:4: expected 'map'"},
      {"type octile\nheight 1\n", "small.map:3: missing 'width N'"},
  };
  for (const Case& c : cases) {
    auto map = ParseMovingAi(c.bytes);
    ASSERT_FALSE(map.ok()) << c.bytes;
    EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument) << c.bytes;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.bytes;
  }
}

TEST(MapIoMovingAiTest, RejectsWrongRowsNamingTheLine) {
  auto short_row = ParseMovingAi("type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  ASSERT_FALSE(short_row.ok());
  EXPECT_EQ(short_row.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(short_row.status().message(),
              HasSubstr("small.map:6: row 1 has 2 characters, expected 3"));

  auto truncated = ParseMovingAi("type octile\nheight 3\nwidth 3\nmap\n...\n...\n");
  ASSERT_FALSE(truncated.ok());
  EXPECT_THAT(truncated.status().message(), HasSubstr("small.map:7: the file ends after 2 of 3"));

  auto extra = ParseMovingAi("type octile\nheight 1\nwidth 3\nmap\n...\n...\n");
  ASSERT_FALSE(extra.ok());
  EXPECT_THAT(extra.status().message(), HasSubstr("small.map:6: more than the 1 rows"));
}

TEST(MapIoMovingAiTest, RejectsHugeHeaderBeforeAllocating) {
  auto huge = ParseMovingAi("type octile\nheight 1000000000\nwidth 1000000000\nmap\n.\n");
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(huge.status().message(), HasSubstr("small.map"));

  // Within the cell limit but more cells than the file has bytes: rejected before allocating.
  auto lying = ParseMovingAi("type octile\nheight 4000\nwidth 4000\nmap\n.\n");
  ASSERT_FALSE(lying.ok());
  EXPECT_EQ(lying.status().code(), absl::StatusCode::kInvalidArgument);

  MapLimits small;
  small.max_cells = 11;
  auto over = ParseMovingAi(kSmallMap, small);
  ASSERT_FALSE(over.ok());
  EXPECT_EQ(over.status().code(), absl::StatusCode::kResourceExhausted);

  small = MapLimits{};
  small.max_file_bytes = 10;
  auto too_long = ParseMovingAi(kSmallMap, small);
  ASSERT_FALSE(too_long.ok());
  EXPECT_EQ(too_long.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(too_long.status().message(), HasSubstr("small.map"));
}

constexpr char kScen[] =
    "version 1\n"
    "0\tmaps/dao/arena.map\t49\t49\t1\t11\t1\t12\t1\n"
    "\n"
    "1\tarena.map\t49\t49\t3\t4\t40\t41\t62.1543\r\n";

TEST(MapIoMovingAiTest, ParsesScenarios) {
  auto scen = ParseScenarios("a.scen", kScen);
  ASSERT_TRUE(scen.ok()) << scen.status();
  ASSERT_EQ(scen->size(), 2u);
  const Scenario& s = (*scen)[1];
  EXPECT_EQ(s.bucket, 1);
  EXPECT_EQ(s.map_name, "arena.map");
  EXPECT_EQ((*scen)[0].map_name, "arena.map");  // path reduced to the file name
  EXPECT_EQ(s.width, 49);
  EXPECT_EQ(s.height, 49);
  EXPECT_EQ(s.start, (Cell{3, 4}));
  EXPECT_EQ(s.goal, (Cell{40, 41}));
  EXPECT_DOUBLE_EQ(s.optimal_length, 62.1543);

  auto old = ParseScenarios("a.scen", "version 1.0\n0\tx.map\t2\t2\t0\t0\t1\t1\t1.41421356\n");
  ASSERT_TRUE(old.ok()) << old.status();
  EXPECT_EQ(old->size(), 1u);
}

TEST(MapIoMovingAiTest, RejectsBadScenarios) {
  struct Case {
    std::string bytes;
    std::string message;
  };
  const Case cases[] = {
      {"version 2\n", "a.scen:1: expected 'version 1'"},
      {"0\tx.map\t2\t2\t0\t0\t1\t1\t1\n", "a.scen:1: expected 'version 1'"},
      {"version 1\n0\tx.map\t2\t2\t0\t0\t1\t1\n",
       "a.scen:2: expected 9 tab-separated fields, got 8"},
      {"version 1\n0 x.map 2 2 0 0 1 1 1\n", "a.scen:2: expected 9 tab-separated fields"},
      {"version 1\n0\tx.map\t2\t2\tz\t0\t1\t1\t1\n", "a.scen:2: field 5 (start_x)"},
      {"version 1\n0\tx.map\t2\t2\t0\t0\t1\t1\tlong\n", "a.scen:2: field 9 (optimal_length)"},
      {"version 1\n0\tx.map\t2\t2\t0\t0\t1\t1\t-1\n", "a.scen:2: field 9 (optimal_length)"},
      {"version 1\n0\tx.map\t2\t2\t0\t0\t2\t1\t1\n", "a.scen:2: goal 2,1 lies outside"},
      {"version 1\n0\t\t2\t2\t0\t0\t1\t1\t1\n", "a.scen:2: field 2 (map) is empty"},
  };
  for (const Case& c : cases) {
    auto scen = ParseScenarios("a.scen", c.bytes);
    ASSERT_FALSE(scen.ok()) << c.bytes;
    EXPECT_EQ(scen.status().code(), absl::StatusCode::kInvalidArgument) << c.bytes;
    EXPECT_THAT(scen.status().message(), HasSubstr(c.message)) << c.bytes;
  }
}

TEST(MapIoMovingAiTest, LoadScenarioFileReportsMissingFile) {
  auto scen = LoadScenarioFile("/nonexistent/none.map.scen");
  ASSERT_FALSE(scen.ok());
  EXPECT_THAT(scen.status().message(), HasSubstr("/nonexistent/none.map.scen"));
}

TEST(MapIoMovingAiTest, LoadsArenaBenchmark) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/arena.map");
  const std::string dir = testing::BenchmarksDir() + "/movingai/";
  auto map = LoadMapFile(dir + "arena.map");
  ASSERT_TRUE(map.ok()) << map.status();
  const OccupancyGrid* grid = map->grid();
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->width(), 49);
  EXPECT_EQ(grid->height(), 49);
  // First data line: "TTTT..."; second: "TTT.....": (3, 1) is the first free cell of row 1.
  EXPECT_TRUE(grid->IsBlocked(Cell{0, 0}));
  EXPECT_TRUE(grid->IsBlocked(Cell{2, 1}));
  EXPECT_TRUE(grid->IsFree(Cell{3, 1}));
  EXPECT_EQ(grid->BlockedCount(), 49 * 49 - 2054);

  auto scen = LoadScenarioFile(dir + "arena.map.scen");
  ASSERT_TRUE(scen.ok()) << scen.status();
  EXPECT_EQ(scen->size(), 160u);
  for (const Scenario& s : *scen) {
    EXPECT_EQ(s.map_name, "arena.map");
    EXPECT_TRUE(grid->IsFree(s.start));
    EXPECT_TRUE(grid->IsFree(s.goal));
  }
}

TEST(MapIoMovingAiTest, LoadsEveryBenchmarkPairWithPassableScenarioEndpoints) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai");
  const std::string dir = testing::BenchmarksDir() + "/movingai/";
  const char* const kNames[] = {"arena",        "den312d",        "den011d",
                                "Berlin_0_256", "Boston_0_256",   "8room_000",
                                "maze512-32-9", "random512-10-0", "AcrosstheCape"};
  for (const char* name : kNames) {
    auto map = LoadMapFile(dir + name + ".map");
    ASSERT_TRUE(map.ok()) << map.status();
    auto scen = LoadScenarioFile(dir + name + ".map.scen");
    ASSERT_TRUE(scen.ok()) << scen.status();
    ASSERT_FALSE(scen->empty()) << name;
    const OccupancyGrid& grid = *map->grid();
    int bad = 0;
    for (const Scenario& s : *scen) {
      EXPECT_EQ(s.map_name, std::string(name) + ".map");
      EXPECT_EQ(s.width, grid.width()) << name;
      EXPECT_EQ(s.height, grid.height()) << name;
      bad += grid.IsBlocked(s.start) || grid.IsBlocked(s.goal);
    }
    EXPECT_EQ(bad, 0) << name;
  }
}

}  // namespace
}  // namespace swarmplan
