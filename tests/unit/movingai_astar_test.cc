// A* against the optimal lengths of the Moving AI benchmark scenarios: every .map with a
// .map.scen beside it in ../shared/benchmarks/movingai, one scenario from every bucket.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "core/geometry/grid_collision.h"
#include "core/geometry/primitives.h"
#include "core/graph/grid_search.h"
#include "core/graph/theta_star.h"
#include "core/map/io/map_io.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

// The scen files print optimal_length either with 8 decimals or with 6 significant digits
// (printf %g: "1176.61", "1.41421"). 6 significant digits bound the relative printing error by
// 5e-6, so 1e-4 relative holds for every file without special cases.
constexpr double kRelativeTolerance = 1e-4;

// Under the sanitizers, which look for memory errors rather than wrong lengths and make A* about
// 3x slower, every fourth bucket; the Release run checks them all.
#ifdef SWARMPLAN_SANITIZED_BUILD
constexpr int kBucketStride = 4;
#else
constexpr int kBucketStride = 1;
#endif

struct BenchmarkPair {
  std::string map_path;
  std::string scen_path;
};

std::vector<BenchmarkPair> FindPairs(const std::string& dir) {
  std::vector<BenchmarkPair> pairs;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".map") continue;
    const std::string scen = entry.path().string() + ".scen";
    if (std::filesystem::exists(scen)) pairs.push_back({entry.path().string(), scen});
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const BenchmarkPair& a, const BenchmarkPair& b) { return a.map_path < b.map_path; });
  return pairs;
}

// One scenario per bucket (per kBucketStride-th bucket); which one rotates with the bucket number
// so that the sample covers every position within a bucket across the file.
std::vector<Scenario> SampleEveryBucket(const std::vector<Scenario>& scenarios) {
  std::map<int, std::vector<const Scenario*>> buckets;
  for (const Scenario& s : scenarios) buckets[s.bucket].push_back(&s);
  std::vector<Scenario> sample;
  for (const auto& [bucket, members] : buckets) {
    if (bucket % kBucketStride != 0) continue;
    sample.push_back(*members[static_cast<size_t>(bucket) % members.size()]);
  }
  return sample;
}

TEST(MovingAiAStarTest, ReproducesOptimalLengthsInEveryBucket) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai");
  const std::vector<BenchmarkPair> pairs =
      FindPairs(::swarmplan::testing::BenchmarksDir() + "/movingai");
  ASSERT_FALSE(pairs.empty()) << "no .map with a .map.scen beside it";
  GridSearchContext context;
  int checked = 0;
  for (const BenchmarkPair& pair : pairs) {
    SCOPED_TRACE(pair.scen_path);
    absl::StatusOr<Map> map = LoadMapFile(pair.map_path);
    ASSERT_TRUE(map.ok()) << map.status();
    const OccupancyGrid* grid = map->grid();
    ASSERT_NE(grid, nullptr);
    absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(pair.scen_path);
    ASSERT_TRUE(scenarios.ok()) << scenarios.status();
    ASSERT_FALSE(scenarios->empty());
    for (const Scenario& s : SampleEveryBucket(*scenarios)) {
      ASSERT_EQ(s.width, grid->width());
      ASSERT_EQ(s.height, grid->height());
      const GridSearchResult r = SearchGrid(*grid, s.start, s.goal, {}, &context);
      ASSERT_TRUE(r.found) << "bucket " << s.bucket << ": no path from " << s.start.x << ","
                           << s.start.y << " to " << s.goal.x << "," << s.goal.y;
      EXPECT_LE(std::abs(r.length - s.optimal_length),
                kRelativeTolerance * std::max(s.optimal_length, 1.0))
          << "bucket " << s.bucket << " from " << s.start.x << "," << s.start.y << " to "
          << s.goal.x << "," << s.goal.y << ": A* " << r.length << ", scen " << s.optimal_length;
      ++checked;
    }
  }
  RecordProperty("scenarios_checked", checked);
}

// Theta* on the same maps, for ten buckets spread over each file: never longer than the optimal
// grid path, never shorter than the straight line, collision-free.
TEST(MovingAiAStarTest, ThetaStarNoLongerThanOptimalGridPaths) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai");
  GridSearchContext context;
  for (const BenchmarkPair& pair : FindPairs(::swarmplan::testing::BenchmarksDir() + "/movingai")) {
    SCOPED_TRACE(pair.scen_path);
    absl::StatusOr<Map> map = LoadMapFile(pair.map_path);
    ASSERT_TRUE(map.ok()) << map.status();
    absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(pair.scen_path);
    ASSERT_TRUE(scenarios.ok()) << scenarios.status();
    const OccupancyGrid& grid = *map->grid();
    const GridCollisionChecker checker(grid);
    const std::vector<Scenario> sample = SampleEveryBucket(*scenarios);
    constexpr size_t kPerFile = 10;
    for (size_t k = 0; k < kPerFile && k < sample.size(); ++k) {
      const Scenario& s = sample[k * sample.size() / std::min(kPerFile, sample.size())];
      const GridSearchResult r = ThetaStar(grid, checker, s.start, s.goal, {}, &context);
      ASSERT_TRUE(r.found) << "bucket " << s.bucket;
      EXPECT_LE(r.length, s.optimal_length * (1 + kRelativeTolerance)) << "bucket " << s.bucket;
      EXPECT_GE(r.length, (grid.CellCenter(s.start) - grid.CellCenter(s.goal)).norm() - 1e-9);
      EXPECT_TRUE(checker.PathFree(CellPathToWorld(grid, r.cells), 0.0)) << "bucket " << s.bucket;
    }
  }
}

// A Theta* path on 8room_000 that passes 0.031 cells from a blocked corner: its reported
// clearance is the exact distance to the nearest blocked square (brute force over every
// square), never negative. Sphere tracing on the distance field reported -0.080 here.
TEST(MovingAiAStarTest, ThetaStarClearanceIsExact) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/8room_000.map");
  const absl::StatusOr<Map> map =
      LoadMapFile(::swarmplan::testing::BenchmarksDir() + "/movingai/8room_000.map");
  ASSERT_TRUE(map.ok()) << map.status();
  const OccupancyGrid& grid = *map->grid();
  const GridCollisionChecker checker(grid);
  const GridSearchResult r = ThetaStar(grid, checker, Cell{148, 116}, Cell{246, 39}, {});
  ASSERT_TRUE(r.found);
  const Path path = CellPathToWorld(grid, r.cells);
  ASSERT_TRUE(checker.PathFree(path, 0.0));
  double exact = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    for (int y = 0; y < grid.height(); ++y) {
      for (int x = 0; x < grid.width(); ++x) {
        if (!grid.IsBlocked(x, y)) continue;
        const std::vector<Point2> square = {Point2(x, y), Point2(x + 1, y), Point2(x + 1, y + 1),
                                            Point2(x, y + 1)};
        exact = std::min(exact,
                         SegmentPolygonDistance(path[i].head<2>(), path[i + 1].head<2>(), square));
      }
    }
  }
  const PathMetrics metrics = EvaluatePath(*map, path, 0.0);
  EXPECT_TRUE(metrics.collision_free);
  EXPECT_GT(metrics.min_clearance, 0.0);
  EXPECT_NEAR(metrics.min_clearance, exact, 1e-12);
  EXPECT_NEAR(metrics.min_clearance, 0.03119, 1e-5);
}

}  // namespace
}  // namespace swarmplan
