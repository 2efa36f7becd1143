#include <string>

#include "core/map/io/map_io.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

absl::StatusOr<Map> ParseAscii(const std::string& bytes, const MapLimits& limits = {}) {
  LoadOptions options;
  options.limits = limits;
  return ParseMap("ascii", {MapFile{"art.txt", bytes}}, options);
}

TEST(MapIoAsciiTest, ParsesRowsWithFirstLineAsYZero) {
  auto map = ParseAscii("..#\n@..\r\n...\n\n\n");
  ASSERT_TRUE(map.ok()) << map.status();
  const OccupancyGrid* grid = map->grid();
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->width(), 3);
  EXPECT_EQ(grid->height(), 3);
  EXPECT_EQ(grid->value(2, 0), 100);
  EXPECT_EQ(grid->value(0, 1), 100);
  EXPECT_EQ(grid->value(0, 0), 0);
  EXPECT_EQ(grid->BlockedCount(), 2);
}

TEST(MapIoAsciiTest, AcceptsMissingFinalNewline) {
  auto map = ParseAscii("..\n.#");
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(map->grid()->value(1, 1), 100);
}

TEST(MapIoAsciiTest, RejectsBadInputNamingTheLine) {
  struct Case {
    std::string bytes;
    absl::StatusCode code;
    std::string message;
  };
  const Case cases[] = {
      {"", absl::StatusCode::kInvalidArgument, "art.txt: no rows"},
      {"\n\n", absl::StatusCode::kInvalidArgument, "art.txt: no rows"},
      {"...\n..\n", absl::StatusCode::kInvalidArgument,
       "art.txt:2: row has 2 characters, expected 3"},
      {"...\n.x.\n", absl::StatusCode::kInvalidArgument, "art.txt:2: column 2: \"x\""},
      {"...\n. .\n", absl::StatusCode::kInvalidArgument, "art.txt:2: column 2: \" \""},
      {"...\n\n...\n", absl::StatusCode::kInvalidArgument, "art.txt:2: blank line inside"},
  };
  for (const Case& c : cases) {
    auto map = ParseAscii(c.bytes);
    ASSERT_FALSE(map.ok()) << c.bytes;
    EXPECT_EQ(map.status().code(), c.code) << c.bytes;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.bytes;
  }
}

TEST(MapIoAsciiTest, RespectsLimits) {
  MapLimits limits;
  limits.max_cells = 5;
  auto map = ParseAscii("...\n...\n", limits);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(map.status().message(), HasSubstr("art.txt"));
}

TEST(MapIoAsciiTest, UnknownFormatAndWrongFileCountAreRejected) {
  auto unknown = ParseMap("bmp", {MapFile{"a.bmp", ""}});
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(unknown.status().message(), HasSubstr("unknown map format \"bmp\""));
  auto two = ParseMap("ascii", {MapFile{"a.txt", "."}, MapFile{"b.txt", "."}});
  ASSERT_FALSE(two.ok());
  EXPECT_THAT(two.status().message(), HasSubstr("needs 1 file"));
}

TEST(MapIoAsciiTest, GuessesFormatsFromExtensions) {
  EXPECT_EQ(GuessMapFormat("a/b/map.yaml"), "ros-yaml-pgm");
  EXPECT_EQ(GuessMapFormat("x.MAP"), "movingai");
  EXPECT_EQ(GuessMapFormat("x.geojson"), "geojson");
  EXPECT_EQ(GuessMapFormat("x.json"), "shapes-json");
  EXPECT_EQ(GuessMapFormat("x.asc"), "terrain-asc");
  EXPECT_EQ(GuessMapFormat("x.csv"), "terrain-csv");
  EXPECT_EQ(GuessMapFormat("x.pgm"), "pgm");
  EXPECT_EQ(GuessMapFormat("x.png"), "png");
  EXPECT_EQ(GuessMapFormat("x.txt"), "ascii");
  EXPECT_EQ(GuessMapFormat("x.bin"), "");
}

}  // namespace
}  // namespace swarmplan
