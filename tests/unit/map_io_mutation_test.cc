// Every loader on damaged input: random byte changes, insertions and truncations of good
// files must give a map or an error naming the file, never a crash (run under ASan in CI).

#include <string>
#include <vector>

#include "core/map/io/map_io.h"
#include "core/random.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "tests/unit/map_io_png_fixtures.h"

namespace swarmplan {
namespace {

std::string Mutate(Rng& rng, std::string bytes) {
  static const char kInteresting[] = "\n\r\t ,.#@-+0123456789e[]{}\":P\xff";
  const int edits = static_cast<int>(rng.UniformInt(1, 4));
  for (int e = 0; e < edits && !bytes.empty(); ++e) {
    const size_t at = static_cast<size_t>(rng.UniformInt(0, bytes.size() - 1));
    const char c = rng.Bernoulli(0.5) ? kInteresting[rng.UniformInt(0, sizeof(kInteresting) - 2)]
                                      : static_cast<char>(rng.UniformInt(0, 255));
    switch (rng.UniformInt(0, 3)) {
      case 0:
        bytes[at] = c;
        break;
      case 1:
        bytes.insert(bytes.begin() + at, c);
        break;
      case 2:
        bytes.erase(at, 1);
        break;
      default:
        bytes.resize(at);
        break;
    }
  }
  return bytes;
}

struct Sample {
  std::string format;
  std::vector<MapFile> files;
};

std::vector<Sample> Samples() {
  const std::string png(reinterpret_cast<const char*>(testing::kRgb16), sizeof(testing::kRgb16));
  const std::string yaml_info = "resolution: 0.05\norigin: [1, 2, 0]\nnegate: 0\nmode: scale\n";
  return {
      {"movingai", {{"m.map", "type octile\nheight 3\nwidth 4\nmap\n.T@.\nGS.W\n....\n"}}},
      {"ascii", {{"m.txt", "..#\n@..\n...\n"}}},
      {"shapes-json",
       {{"m.json", R"({"bounds": [0, 0, 10, 10], "circles": [{"center": [2, 2], "radius": 1}],
                      "polygons": [[[4, 4], [6, 4], [5, 6]]]})"}}},
      {"geojson",
       {{"m.geojson", R"({"type": "FeatureCollection", "bounds": [0, 0, 9, 9], "features": [
            {"type": "Feature", "geometry": {"type": "Polygon",
             "coordinates": [[[1, 1], [3, 1], [3, 3], [1, 1]]]}}]})"}}},
      {"terrain-asc",
       {{"m.asc",
         "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
         "NODATA_value -9999\n 1 2 -9999\n4 5 6\n"}}},
      {"terrain-csv", {{"m.csv", "1,2,3\n4,5,6\n"}}},
      {"terrain-pgm", {{"m.pgm", "P2 3 2 255\n0 1 2\n3 4 5\n"}}},
      {"pgm", {{"m.pgm", std::string("P5 3 2 255\n\x00\xff\x96\xff\x64\x00", 17)}}},
      {"png", {{"m.png", png}}},
      {"ros-yaml-pgm",
       {{"m.yaml", "image: m.pgm\n" + yaml_info}, {"m.pgm", "P2 3 2 255\n0 255 150\n255 100 0\n"}}},
      {"ros-yaml-pgm", {{"m.yaml", "image: m.png\n" + yaml_info}, {"m.png", png}}},
  };
}

TEST(MapIoMutationTest, DamagedFilesGiveMapsOrErrorsNamingTheFile) {
  Rng rng(2024);
  LoadOptions options;
  options.limits.max_cells = 1 << 16;
  for (const Sample& sample : Samples()) {
    auto good = ParseMap(sample.format, sample.files, options);
    ASSERT_TRUE(good.ok()) << sample.format << ": " << good.status();
    int errors = 0;
    for (int trial = 0; trial < 400; ++trial) {
      std::vector<MapFile> files = sample.files;
      MapFile& victim = files[rng.UniformInt(0, files.size() - 1)];
      victim.bytes = Mutate(rng, victim.bytes);
      auto map = ParseMap(sample.format, files, options);
      if (map.ok()) continue;
      ++errors;
      const absl::StatusCode code = map.status().code();
      EXPECT_TRUE(code == absl::StatusCode::kInvalidArgument ||
                  code == absl::StatusCode::kResourceExhausted)
          << sample.format << ": " << map.status();
      EXPECT_THAT(std::string(map.status().message()), ::testing::HasSubstr(victim.name))
          << sample.format << ": " << map.status();
    }
    EXPECT_GT(errors, 0) << sample.format;
  }
}

}  // namespace
}  // namespace swarmplan
