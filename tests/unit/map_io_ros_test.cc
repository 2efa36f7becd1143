#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/map/io/formats.h"
#include "core/map/io/map_io.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "tests/unit/map_io_png_fixtures.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

using testing::kColour;
using testing::kGrey8;
using testing::kGreyAlpha;
using testing::kPalette;
using testing::kRgb16;
using testing::kRgb8;

std::string Bytes(const unsigned char* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}
#define BYTES(array) Bytes(array, sizeof(array))

constexpr char kPlainPgm[] =
    "P2\n"
    "# a comment\n"
    "3 2\n"
    "255\n"
    "0 255 150\n"
    "255 100 0\n";

std::string BinaryPgm() {
  return std::string("P5\n3 2\n255\n") + std::string("\x00\xff\x96\xff\x64\x00", 6);
}

constexpr char kYaml[] =
    "image: map.pgm\n"
    "resolution: 0.05\n"
    "origin: [-1.5, 2.0, 0.0]\n"
    "negate: 0\n"
    "occupied_thresh: 0.65\n"
    "free_thresh: 0.196\n";

absl::StatusOr<Map> ParseRos(const std::string& yaml, const std::string& image,
                             const MapLimits& limits = {}) {
  LoadOptions options;
  options.limits = limits;
  return ParseMap("ros-yaml-pgm", {MapFile{"map.yaml", yaml}, MapFile{"map.pgm", image}}, options);
}

// Grid values listed top row first (image order), i.e. y = 1 then y = 0.
std::vector<int> TopDown(const OccupancyGrid& grid) {
  std::vector<int> values;
  for (int y = grid.height() - 1; y >= 0; --y) {
    for (int x = 0; x < grid.width(); ++x) values.push_back(grid.value(x, y));
  }
  return values;
}

const std::vector<int> kTrinary = {100, 0, -1, 0, -1, 100};

TEST(MapIoRosMapTest, ReadsYamlAndPlainPgmWithImageRowZeroAtTheTop) {
  auto map = ParseRos(kYaml, kPlainPgm);
  ASSERT_TRUE(map.ok()) << map.status();
  const OccupancyGrid* grid = map->grid();
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->width(), 3);
  EXPECT_EQ(grid->height(), 2);
  EXPECT_DOUBLE_EQ(grid->resolution(), 0.05);
  EXPECT_EQ(grid->origin(), Point2(-1.5, 2.0));
  EXPECT_EQ(grid->value(0, 1), 100);  // top-left pixel, black
  EXPECT_EQ(grid->value(0, 0), 0);    // bottom-left pixel, white
  EXPECT_EQ(TopDown(*grid), kTrinary);
}

TEST(MapIoRosMapTest, BinaryPgmMatchesPlainPgm) {
  auto map = ParseRos(kYaml, BinaryPgm());
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(TopDown(*map->grid()), kTrinary);
}

TEST(MapIoRosMapTest, SixteenBitPgmIsScaledByMaxval) {
  std::string pgm = "P5 3 2 65535\n";
  for (int g : {0, 255, 150, 255, 100, 0}) {
    const int v = g * 257;
    pgm += static_cast<char>(v >> 8);
    pgm += static_cast<char>(v & 255);
  }
  auto map = ParseRos(kYaml, pgm);
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(TopDown(*map->grid()), kTrinary);
}

TEST(MapIoRosMapTest, EveryPngColourTypeGivesTheSameGrid) {
  for (const auto& [name, bytes] :
       {std::pair{"grey8", BYTES(kGrey8)}, std::pair{"rgb8", BYTES(kRgb8)},
        std::pair{"rgb16", BYTES(kRgb16)}, std::pair{"palette", BYTES(kPalette)},
        std::pair{"grey+alpha", BYTES(kGreyAlpha)}}) {
    auto map = ParseRos(kYaml, bytes);
    ASSERT_TRUE(map.ok()) << name << ": " << map.status();
    EXPECT_EQ(TopDown(*map->grid()), kTrinary) << name;
  }
}

TEST(MapIoRosMapTest, ColourPixelsAverageTheirChannels) {
  auto map = ParseRos(std::string(kYaml) + "mode: raw\n", BYTES(kColour));
  ASSERT_FALSE(map.ok());  // (255 + 255 + 252) / 3 = 254 is not a raw value
  EXPECT_THAT(map.status().message(), HasSubstr("map.pgm: pixel 1,0 (column, row) has value 254"));
  auto trinary = ParseRos(kYaml, BYTES(kColour));
  ASSERT_TRUE(trinary.ok()) << trinary.status();
  EXPECT_EQ(trinary->grid()->value(0, 0), 100);  // mean 60: p = 0.76
  EXPECT_EQ(trinary->grid()->value(1, 0), 0);
}

TEST(MapIoRosMapTest, NegateSwapsFreeAndOccupied) {
  std::string yaml = kYaml;
  yaml.replace(yaml.find("negate: 0"), 9, "negate: 1");
  auto map = ParseRos(yaml, kPlainPgm);
  ASSERT_TRUE(map.ok()) << map.status();
  // 150 negated is 105: p = 0.588, still unknown; 100 negated is 155: p = 0.39.
  EXPECT_EQ(TopDown(*map->grid()), (std::vector<int>{0, 100, -1, 100, -1, 0}));
  auto as_bool =
      ParseRos(std::string(kYaml).replace(yaml.find("negate: 1"), 9, "negate: true"), kPlainPgm);
  ASSERT_TRUE(as_bool.ok()) << as_bool.status();
  EXPECT_EQ(TopDown(*as_bool->grid()), TopDown(*map->grid()));
}

TEST(MapIoRosMapTest, ScaleModeInterpolatesBetweenThresholds) {
  auto map = ParseRos(std::string(kYaml) + "mode: scale\n", kPlainPgm);
  ASSERT_TRUE(map.ok()) << map.status();
  // 150: p = 105/255, 99 * (p - 0.196) / (0.65 - 0.196) = 47.05; 100: p = 155/255 -> 89.8.
  EXPECT_EQ(TopDown(*map->grid()), (std::vector<int>{100, 0, 47, 0, 89, 100}));
  // A fully transparent pixel is unknown in scale mode, as in map_server.
  auto alpha = ParseRos(std::string(kYaml) + "mode: scale\n", BYTES(kGreyAlpha));
  ASSERT_TRUE(alpha.ok()) << alpha.status();
  EXPECT_EQ(TopDown(*alpha->grid()), (std::vector<int>{100, 0, -1, 0, 89, 100}));
}

TEST(MapIoRosMapTest, RawModeKeepsValues) {
  auto map = ParseRos(std::string(kYaml) + "mode: raw\n", "P2 2 2 255\n0 100\n255 42\n");
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(TopDown(*map->grid()), (std::vector<int>{0, 100, -1, 42}));
  auto bad = ParseRos(std::string(kYaml) + "mode: raw\n", kPlainPgm);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(bad.status().message(), HasSubstr("map.pgm: pixel 2,0 (column, row) has value 150"));
}

TEST(MapIoRosMapTest, RejectsBadYamlNamingTheField) {
  struct Case {
    std::string yaml;
    std::string message;
  };
  const Case cases[] = {
      {"image: [unclosed\n", "map.yaml: not valid YAML"},
      {"- a\n- b\n", "map.yaml: the YAML must be a mapping"},
      {"resolution: 0.05\norigin: [0, 0, 0]\n", "map.yaml: image: missing"},
      {"image: m.pgm\norigin: [0, 0, 0]\n", "map.yaml: resolution: missing"},
      {"image: m.pgm\nresolution: -1\norigin: [0, 0, 0]\n",
       "map.yaml: resolution: must be positive"},
      {"image: m.pgm\nresolution: fine\norigin: [0, 0, 0]\n",
       "map.yaml: resolution: must be a number"},
      {"image: m.pgm\nresolution: 1\n", "map.yaml: origin: missing"},
      {"image: m.pgm\nresolution: 1\norigin: [0, 0]\n", "map.yaml: origin: must be [x, y, yaw]"},
      {"image: m.pgm\nresolution: 1\norigin: [0, x, 0]\n", "map.yaml: origin[1]: must be a number"},
      {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0.5]\n",
       "map.yaml: origin[2]: a rotated map (yaw != 0) is not supported"},
      {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 2\n",
       "map.yaml: negate: must be 0, 1, true or false"},
      {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\noccupied_thresh: 1.5\n",
       "map.yaml: occupied_thresh: must be in [0, 1]"},
      {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nfree_thresh: 0.7\n",
       "map.yaml: free_thresh: must be below occupied_thresh"},
      {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: fancy\n",
       "map.yaml: mode: must be trinary, scale or raw, got \"fancy\""},
  };
  for (const Case& c : cases) {
    auto map = ParseRos(c.yaml, kPlainPgm);
    ASSERT_FALSE(map.ok()) << c.yaml;
    EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument) << c.yaml;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.yaml;
  }
}

// A YAML padded with a comment to the limit is read; one byte more is refused before parsing.
TEST(MapIoRosMapTest, YamlOverItsSizeLimitIsRefusedNamingTheFile) {
  const std::string at_limit =
      std::string(kYaml) + "#" + std::string(kMaxRosYamlBytes - 1 - sizeof(kYaml), 'x') + "\n";
  ASSERT_EQ(at_limit.size(), kMaxRosYamlBytes);
  EXPECT_TRUE(ParseRos(at_limit, kPlainPgm).ok());
  EXPECT_TRUE(RosMapImagePath(MapFile{"map.yaml", at_limit}).ok());
  const std::string over = at_limit + " ";
  auto map = ParseRos(over, kPlainPgm);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(map.status().message(), HasSubstr("map.yaml: 4097 bytes exceed the limit of 4096"));
  absl::StatusOr<std::string> image = RosMapImagePath(MapFile{"map.yaml", over});
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.status().code(), absl::StatusCode::kResourceExhausted);
}

TEST(MapIoRosMapTest, TheImageFileMustHaveTheBaseNameTheYamlNames) {
  for (const char* named : {"other.pgm", "maps/other.pgm", "map.pgm/", "map.PGM"}) {
    const std::string yaml =
        std::string("image: ") + named + "\nresolution: 1\norigin: [0, 0, 0]\n";
    auto map = ParseRos(yaml, kPlainPgm);
    ASSERT_FALSE(map.ok()) << named;
    EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument) << named;
    EXPECT_THAT(map.status().message(), HasSubstr(std::string("map.yaml: image: names \"") + named +
                                                  "\" but the image file given is \"map.pgm\""));
  }
  // A folder in either name does not matter: the base names match.
  for (const char* named : {"map.pgm", "maps/map.pgm", "/srv/maps/map.pgm"}) {
    const std::string yaml =
        std::string("image: ") + named + "\nresolution: 1\norigin: [0, 0, 0]\n";
    auto map = ParseMap("ros-yaml-pgm",
                        {MapFile{"up/map.yaml", yaml}, MapFile{"elsewhere/map.pgm", kPlainPgm}});
    EXPECT_TRUE(map.ok()) << named << ": " << map.status();
  }
}

TEST(MapIoRosMapTest, RejectsBadImagesNamingTheFileAndLine) {
  struct Case {
    std::string image;
    std::string message;
  };
  std::string truncated_png = BYTES(kGrey8);
  truncated_png.resize(40);
  std::string corrupt_png = BYTES(kGrey8);
  corrupt_png[20] ^= 0x10;  // inside IHDR: its CRC no longer matches
  const Case cases[] = {
      {"", "map.pgm: not a PGM (P2/P5) or PNG image"},
      {"GIF89a", "map.pgm: not a PGM (P2/P5) or PNG image"},
      {"P2\n3\n", "map.pgm:2: PGM header ends before its height"},
      {"P2\n3 2\n# c\nwhite\n", "map.pgm:4: PGM maxval must be an integer in 1..65535"},
      {"P2 0 2 255\n", "map.pgm:1: PGM width must be an integer"},
      {"P2 3 2 255\n0 1 2\n3 4\n", "map.pgm:3: PGM pixel data ends after 5 of 6 values"},
      {"P2 3 2 255\n0 1 2\n3 4 256\n", "map.pgm:3: pixel 2,1 (column, row) must be an integer"},
      {"P2 3 2 255\n0 1 2\n3 x 5\n", "map.pgm:3: pixel 1,1 (column, row) must be an integer"},
      {std::string("P5 3 2 255\n\x01\x02\x03", 14), "map.pgm: PGM pixel data is truncated"},
      {std::string("P5 2 1 100\n\x01\xff", 13), "map.pgm: pixel 1,0 (column, row) has value 255"},
      {truncated_png, "map.pgm: bad PNG"},
      {corrupt_png, "map.pgm: bad PNG"},
  };
  for (const Case& c : cases) {
    auto map = ParseRos(kYaml, c.image);
    ASSERT_FALSE(map.ok()) << c.image;
    EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument) << c.image;
    EXPECT_THAT(map.status().message(), HasSubstr(c.message)) << c.image;
  }
}

TEST(MapIoRosMapTest, RespectsLimitsBeforeDecoding) {
  MapLimits limits;
  limits.max_cells = 5;
  for (const std::string& image : {std::string(kPlainPgm), BinaryPgm(), BYTES(kGrey8),
                                   std::string("P5 100000 100000 255\n")}) {
    auto map = ParseRos(kYaml, image, limits);
    ASSERT_FALSE(map.ok());
    EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted) << map.status();
    EXPECT_THAT(map.status().message(), HasSubstr("map.pgm"));
  }
  limits = MapLimits{};
  limits.max_file_bytes = 30;
  auto map = ParseRos(kYaml, kPlainPgm, limits);
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(map.status().message(), HasSubstr("map.yaml"));
}

TEST(MapIoRosMapTest, ImageAloneUsesMapServerDefaults) {
  for (const auto& [format, bytes] :
       {std::pair{"pgm", std::string(kPlainPgm)}, std::pair{"png", BYTES(kRgb16)}}) {
    auto map = ParseMap(format, {MapFile{"alone", bytes}});
    ASSERT_TRUE(map.ok()) << map.status();
    EXPECT_EQ(map->grid()->resolution(), 1.0);
    EXPECT_EQ(map->grid()->origin(), Point2::Zero());
    EXPECT_EQ(TopDown(*map->grid()), kTrinary);
  }
}

class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::path(::testing::TempDir()) /
            ("swarmplan_map_io_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string Write(const std::string& name, const std::string& bytes) const {
    const std::string file = (path_ / name).string();
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
  }

 private:
  std::filesystem::path path_;
};

TEST(MapIoRosMapTest, LoadMapFileReadsTheImageBesideTheYaml) {
  TempDir dir;
  dir.Write("map.pgm", BinaryPgm());
  const std::string yaml = dir.Write("map.yaml", kYaml);
  auto map = LoadMapFile(yaml);
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(TopDown(*map->grid()), kTrinary);

  const std::string missing = dir.Write("other.yaml",
                                        "image: nothere.pgm\nresolution: 1\n"
                                        "origin: [0, 0, 0]\n");
  auto absent = LoadMapFile(missing);
  ASSERT_FALSE(absent.ok());
  EXPECT_THAT(absent.status().message(), HasSubstr("nothere.pgm"));
}

TEST(MapIoRosMapTest, LoadsTheSlamPngs) {
  SWARMPLAN_REQUIRE_BENCHMARKS("occupancy");
  TempDir dir;
  struct Png {
    const char* name;
    int width;
    int height;
    int64_t occupied;
    int64_t unknown;
    Cell occupied_cell;  // occupied, while its vertical mirror is free
  };
  // Counts from an independent Python decoder with the same thresholds.
  const Png pngs[] = {{"intel-lab.png", 579, 581, 16796, 13342, Cell{183, 580}},
                      {"freiburg.png", 911, 368, 15237, 16049, Cell{151, 348}}};
  for (const Png& png : pngs) {
    const std::string yaml =
        dir.Write(std::string(png.name) + ".yaml",
                  "image: " + testing::BenchmarksDir() + "/occupancy/" + png.name +
                      "\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                      "free_thresh: 0.196\n");
    auto map = LoadMapFile(yaml);
    ASSERT_TRUE(map.ok()) << map.status();
    const OccupancyGrid& grid = *map->grid();
    EXPECT_EQ(grid.width(), png.width);
    EXPECT_EQ(grid.height(), png.height);
    int64_t occupied = 0, unknown = 0;
    for (int8_t v : grid.cells()) {
      occupied += v == 100;
      unknown += v == -1;
    }
    EXPECT_EQ(occupied, png.occupied) << png.name;
    EXPECT_EQ(unknown, png.unknown) << png.name;
    EXPECT_EQ(grid.value(png.occupied_cell.x, png.occupied_cell.y), 100) << png.name;
    EXPECT_EQ(grid.value(png.occupied_cell.x, png.height - 1 - png.occupied_cell.y), 0) << png.name;
  }
}

}  // namespace
}  // namespace swarmplan
