#include <cmath>
#include <string>

#include "core/map/io/map_io.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

absl::StatusOr<Map> Parse(const std::string& format, const std::string& name,
                          const std::string& bytes, const LoadOptions& options = {}) {
  return ParseMap(format, {MapFile{name, bytes}}, options);
}

// 3 columns x 2 rows; mixed-case keys, *center origin, NODATA, leading spaces and runs of spaces.
constexpr char kAsc[] =
    "NCOLS 3\n"
    "nrows        2\n"
    "XllCenter 100.5\n"
    "yllcenter   200.5\n"
    "cellsize 1\n"
    "NODATA_value -9999\n"
    "   10   11.5 -9999\n"
    "20 21 22.25\n";

TEST(MapIoTerrainAscTest, ReadsHeaderAndRowsNorthFirst) {
  auto map = Parse("terrain-asc", "dem.asc", kAsc);
  ASSERT_TRUE(map.ok()) << map.status();
  const Terrain* t = map->terrain();
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->width(), 3);
  EXPECT_EQ(t->depth(), 2);
  EXPECT_EQ(t->cell_size(), 1.0);
  EXPECT_EQ(t->origin(), Point2(100.0, 200.0));          // centre of the SW cell minus half a cell
  EXPECT_EQ(t->CellCentre(0, 0), Point2(100.5, 200.5));  // the file's xllcenter, yllcenter
  EXPECT_EQ(t->max_xy(), Point2(102.5, 201.5));
  EXPECT_DOUBLE_EQ(t->GroundAt(Point2(101, 201.5)), (10.0 + 11.5) / 2);
  EXPECT_EQ(t->HeightAt(0, 1), 10.0);  // first value of the file: the NW corner
  EXPECT_EQ(t->HeightAt(1, 1), 11.5);
  EXPECT_TRUE(std::isnan(t->HeightAt(2, 1)));  // NODATA
  EXPECT_EQ(t->HeightAt(0, 0), 20.0);          // last line: the south row
  EXPECT_EQ(t->HeightAt(2, 0), 22.25);
  EXPECT_EQ(t->min_height(), 10.0);
  EXPECT_EQ(t->max_height(), 22.25);
}

TEST(MapIoTerrainAscTest, CornerOriginCrlfAndNoNodata) {
  auto map = Parse("terrain-asc", "dem.asc",
                   "ncols 2\r\nnrows 2\r\nxllcorner -5\r\nyllcorner 7\r\ncellsize 2.5\r\n"
                   "1 2\r\n3 4");
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(map->terrain()->origin(), Point2(-5, 7));
  EXPECT_EQ(map->terrain()->HeightAt(1, 0), 4.0);
  EXPECT_EQ(map->terrain()->cell_size(), 2.5);
  EXPECT_EQ(map->terrain()->CellCentre(1, 1), Point2(-5 + 1.5 * 2.5, 7 + 1.5 * 2.5));
  EXPECT_EQ(map->terrain()->ToCell(Point2(-5 + 1.25, 7 + 2.5)), Point2(0, 0.5));
}

TEST(MapIoTerrainAscTest, CeilingOption) {
  LoadOptions options;
  options.terrain_ceiling = 100;
  auto map = Parse("terrain-asc", "dem.asc", kAsc, options);
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(map->terrain()->ceiling(), 100.0);
  options.terrain_ceiling = 5;  // below the ground
  auto low = Parse("terrain-asc", "dem.asc", kAsc, options);
  ASSERT_FALSE(low.ok());
  EXPECT_THAT(low.status().message(), HasSubstr("dem.asc: ceiling 5"));
}

TEST(MapIoTerrainAscTest, RejectsBadInputNamingTheLine) {
  const std::string header =
      "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\n";
  struct Case {
    std::string bytes;
    std::string message;
  };
  const Case cases[] = {
      {header + "1 2 3\n4 5\n", "dem.asc:8: data row 2 has 2 values, ncols says 3"},
      {header + "1 2 3\n4 5 6 7\n", "dem.asc:8: data row 2 has 4 values, ncols says 3"},
      {header + "1 2 3\n4 five 6\n", "dem.asc:8: value 2 is not a number: \"five\""},
      {header + "1 2 3\n4 nan 6\n", "dem.asc:8: value 2 is not a number"},
      {header + "1 2 3\n", "dem.asc:8: the file ends after 1 of the 2 data rows"},
      {header + "1 2 3\n4 5 6\n7 8 9\n", "dem.asc:9: more than the 2 data rows"},
      {"ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\n1 2 3\n4 5 6\n",
       "dem.asc:5: the header lacks 'cellsize'"},
      {"ncols 3\nnrows 2\nyllcorner 0\ncellsize 1\n1 2 3\n4 5 6\n",
       "dem.asc:5: the header needs exactly one of 'xllcorner' and 'xllcenter'"},
      {"ncols 3\nnrows 2\nxllcorner 0\nxllcenter 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 5 6\n",
       "dem.asc:7: the header needs exactly one of 'xllcorner' and 'xllcenter'"},
      {"ncols 3\nncols 3\n", "dem.asc:2: header key ncols given twice"},
      {"ncols 3\nrows 2\n", "dem.asc:2: unknown header key \"rows\""},
      {"ncols three\n", "dem.asc:1: expected 'ncols NUMBER'"},
      {"ncols 2.5\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n",
       "dem.asc: header ncols must be a positive integer, got 2.5"},
      {"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 0\n1 2\n3 4\n",
       "dem.asc: header cellsize must be positive"},
      {"ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nnodata_value 1\n1 1\n1 1\n",
       "dem.asc: terrain has no cell with data"},
      {"ncols 1000\nnrows 1000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2\n",
       "dem.asc: the header declares 1000 x 1000 values, more than"},
  };
  for (const Case& c : cases) {
    auto map = Parse("terrain-asc", "dem.asc", c.bytes);
    ASSERT_FALSE(map.ok()) << c.bytes;
    EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument) << c.bytes;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.bytes;
  }
}

TEST(MapIoTerrainAscTest, RespectsLimits) {
  LoadOptions options;
  options.limits.max_cells = 5;
  auto small = Parse("terrain-asc", "dem.asc", kAsc, options);
  ASSERT_FALSE(small.ok());
  EXPECT_EQ(small.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(small.status().message(), HasSubstr("dem.asc"));

  auto huge = Parse("terrain-asc", "dem.asc",
                    "ncols 4000000000\nnrows 4000000000\nxllcorner 0\nyllcorner 0\ncellsize 1\n");
  ASSERT_FALSE(huge.ok());
  EXPECT_THAT(huge.status().message(), HasSubstr("dem.asc"));

  options = LoadOptions{};
  options.limits.max_file_bytes = 16;
  auto bytes = Parse("terrain-asc", "dem.asc", kAsc, options);
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().code(), absl::StatusCode::kResourceExhausted);
}

TEST(MapIoTerrainAscTest, LoadsEveryBenchmarkDem) {
  SWARMPLAN_REQUIRE_BENCHMARKS("terrain");
  struct Dem {
    const char* name;
    int width;
    int depth;
    double north_west;  // first value of the file
    double south_east;  // last value of the file
    double min;
    double max;
    int no_data;
  };
  // From an independent Python reading of the files (see benchmarks/README.md for the table).
  const Dem dems[] = {
      {"alps_tiny.asc", 68, 39, 863, 914, 605, 926, 0},
      {"alps_small.asc", 63, 45, 2302, 2111, 1862, 2949, 0},
      {"alps_medium.asc", 110, 69, 1692, 1858, 1335, 2437, 0},
      {"DEM-kootenai_37x50_1x1.asc", 50, 37, 543.340026855468977, 539.559997558594,
       537.359985351562, 543.809997558594, 0},
      {"west_bijou_gully.asc", 43, 89, NAN, NAN, 1680.7793918185764, 1725.4326307508682, 2739},
  };
  for (const Dem& d : dems) {
    auto map = LoadMapFile(testing::BenchmarksDir() + "/terrain/" + d.name);
    ASSERT_TRUE(map.ok()) << map.status();
    const Terrain* t = map->terrain();
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->width(), d.width) << d.name;
    EXPECT_EQ(t->depth(), d.depth) << d.name;
    if (std::isnan(d.north_west)) {
      EXPECT_TRUE(std::isnan(t->HeightAt(0, d.depth - 1))) << d.name;
    } else {
      EXPECT_DOUBLE_EQ(t->HeightAt(0, d.depth - 1), d.north_west) << d.name;
      EXPECT_DOUBLE_EQ(t->HeightAt(d.width - 1, 0), d.south_east) << d.name;
    }
    EXPECT_NEAR(t->min_height(), d.min, 1e-9) << d.name;
    EXPECT_NEAR(t->max_height(), d.max, 1e-9) << d.name;
    int no_data = 0;
    for (double h : t->heights()) no_data += std::isnan(h);
    EXPECT_EQ(no_data, d.no_data) << d.name;
  }
}

TEST(MapIoTerrainCsvTest, ReadsRowsNorthFirst) {
  auto map = Parse("terrain-csv", "h.csv", "1, 2 ,3\r\n4,nan,6\n\n");
  ASSERT_TRUE(map.ok()) << map.status();
  const Terrain* t = map->terrain();
  EXPECT_EQ(t->width(), 3);
  EXPECT_EQ(t->depth(), 2);
  EXPECT_EQ(t->HeightAt(0, 1), 1.0);
  EXPECT_EQ(t->HeightAt(1, 1), 2.0);
  EXPECT_TRUE(std::isnan(t->HeightAt(1, 0)));
  EXPECT_EQ(t->HeightAt(2, 0), 6.0);
  EXPECT_EQ(t->origin(), Point2::Zero());
}

TEST(MapIoTerrainCsvTest, RejectsBadInputNamingTheLine) {
  struct Case {
    std::string bytes;
    absl::StatusCode code;
    std::string message;
  };
  const Case cases[] = {
      {"", absl::StatusCode::kInvalidArgument, "h.csv: no rows"},
      {"1,2\n3\n", absl::StatusCode::kInvalidArgument,
       "h.csv:2: row has 1 values, the first row has 2"},
      {"1,2\n3,x\n", absl::StatusCode::kInvalidArgument, "h.csv:2: column 2 is not a number"},
      {"1,2\n3,\n", absl::StatusCode::kInvalidArgument, "h.csv:2: column 2 is not a number"},
      {"1,2\n", absl::StatusCode::kInvalidArgument, "h.csv: terrain size 2 x 1 must be at least"},
  };
  for (const Case& c : cases) {
    auto map = Parse("terrain-csv", "h.csv", c.bytes);
    ASSERT_FALSE(map.ok()) << c.bytes;
    EXPECT_EQ(map.status().code(), c.code) << c.bytes;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.bytes;
  }
  LoadOptions options;
  options.limits.max_cells = 3;
  auto big = Parse("terrain-csv", "h.csv", "1,2\n3,4\n", options);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.status().code(), absl::StatusCode::kResourceExhausted);
}

TEST(MapIoTerrainImageTest, GreyLevelTimesScaleWithTopRowNorth) {
  LoadOptions options;
  options.terrain_height_scale = 0.5;
  auto map = Parse("terrain-pgm", "h.pgm", "P2 3 2 1000\n0 10 20\n30 40 1000\n", options);
  ASSERT_TRUE(map.ok()) << map.status();
  const Terrain* t = map->terrain();
  EXPECT_EQ(t->width(), 3);
  EXPECT_EQ(t->depth(), 2);
  EXPECT_EQ(t->HeightAt(0, 1), 0.0);
  EXPECT_EQ(t->HeightAt(2, 1), 10.0);
  EXPECT_EQ(t->HeightAt(0, 0), 15.0);
  EXPECT_EQ(t->HeightAt(2, 0), 500.0);  // grey levels keep the image's own range (maxval)
}

TEST(MapIoTerrainImageTest, RejectsBadScaleAndBadImages) {
  LoadOptions options;
  options.terrain_height_scale = -1;
  auto scale = Parse("terrain-pgm", "h.pgm", "P2 2 2 255\n0 1\n2 3\n", options);
  ASSERT_FALSE(scale.ok());
  EXPECT_THAT(scale.status().message(), HasSubstr("h.pgm: terrain_height_scale"));
  auto bad = Parse("terrain-pgm", "h.pgm", "P2 2 2 255\n0 1\n2\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(bad.status().message(), HasSubstr("h.pgm:3: PGM pixel data ends after 3 of 4"));
  options = LoadOptions{};
  options.limits.max_cells = 3;
  auto big = Parse("terrain-pgm", "h.pgm", "P2 2 2 255\n0 1\n2 3\n", options);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.status().code(), absl::StatusCode::kResourceExhausted);
}

}  // namespace
}  // namespace swarmplan
