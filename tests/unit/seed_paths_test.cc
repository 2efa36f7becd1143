#include "core/seeds/seed_paths.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/map/io/map_io.h"
#include "core/map/occupancy_grid.h"
#include "core/optimum.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "gtest/gtest.h"
#include "tests/unit/contract_checks.h"
#include "tests/unit/seed_test_maps.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using seed_testing::BlockWorld;
using seed_testing::Clearance;
using seed_testing::CrossingX;
using seed_testing::TwoDoorGrid;

Problem ProblemOn(const MapPtr& map, const Point2& start, const Point2& goal) {
  Problem problem;
  problem.map = map;
  problem.start = Point3(start.x(), start.y(), 0);
  problem.goal = Point3(goal.x(), goal.y(), 0);
  return problem;
}

void ExpectValidSeeds(const Problem& problem, const std::vector<SeedPath>& seeds) {
  for (const SeedPath& seed : seeds) {
    ASSERT_GE(seed.path.size(), 2u);
    EXPECT_EQ(seed.path.front(), problem.start);
    EXPECT_EQ(seed.path.back(), problem.goal);
    // Exact paths may touch a polygon's corner (the infimum) but never enter it.
    EXPECT_GE(Clearance(*problem.map, seed.path), 0.0);
    EXPECT_NEAR(seed.length, PathLength(seed.path), 1e-9);
  }
}

TEST(SeedPathsTest, GridSeedsTakeOneDoorEachShortestFirst) {
  const Problem problem = ProblemOn(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5});
  absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 3, StopToken());
  ASSERT_TRUE(seeds.ok()) << seeds.status();
  ASSERT_EQ(seeds->size(), 2u) << "two doors, two corridors";
  ExpectValidSeeds(problem, *seeds);
  const Optimum optimum = ComputeOptimum(DefaultRegistry(), problem, absl::Seconds(10));
  ASSERT_TRUE(optimum.known);
  EXPECT_NEAR((*seeds)[0].length, optimum.length, 1e-9) << "the exact optimum comes first";
  EXPECT_LE((*seeds)[0].length, (*seeds)[1].length);
  const double first = CrossingX((*seeds)[0].path, 15.5),
               second = CrossingX((*seeds)[1].path, 15.5);
  EXPECT_TRUE(first >= 30 && first <= 34) << first;
  EXPECT_TRUE(second >= 4 && second <= 8) << second;
}

// Two ways from the lower half to the upper: a door one cell wide (room for the hard clearance
// only) straight between start and goal, and far to the left a diagonal gap between two walls'
// ends, sqrt(5) wide. A fleet with a hard clearance of 0.5 and a preferred one of 2.5 finds no
// path keeping 2.5 or halfway (1.5), but one keeping a quarter of the way (1.0): through the gap,
// where a curve has room, not through the door.
TEST(SeedPathsTest, FleetSeedsTakeTheGapWithRoomOverTheShorterPinch) {
  std::vector<int8_t> cells(40 * 30, OccupancyGrid::kFree);
  for (int x = 0; x <= 10; ++x) cells[10 * 40 + x] = OccupancyGrid::kOccupied;
  for (int x = 13; x < 40; ++x) {
    if (x != 30) cells[12 * 40 + x] = OccupancyGrid::kOccupied;
  }
  const MapPtr map =
      std::make_shared<const Map>(Map::Data(*OccupancyGrid::Create(40, 30, std::move(cells))));
  Problem problem = ProblemOn(map, {30.5, 5.5}, {30.5, 20.5});
  problem.clearance = 0.5;
  absl::StatusOr<std::vector<SeedPath>> hard = FindSeedPaths(problem, 1, StopToken());
  ASSERT_TRUE(hard.ok()) << hard.status();
  ASSERT_EQ(hard->size(), 1u);
  EXPECT_NEAR(CrossingX(hard->front().path, 12.5), 30.5, 1e-9) << "without a fleet: the door";

  problem.fleet.preferred_clearance = 2.5;
  absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 1, StopToken());
  ASSERT_TRUE(seeds.ok()) << seeds.status();
  ASSERT_EQ(seeds->size(), 1u);
  ExpectValidSeeds(problem, *seeds);
  EXPECT_GE(Clearance(*map, seeds->front().path), 1.0 - 1e-9);
  EXPECT_LT(CrossingX(seeds->front().path, 11.5), 13.0) << "through the gap";
}

TEST(SeedPathsTest, ShapeWorldSeedsPassOnEitherSide) {
  const Problem problem = ProblemOn(BlockWorld(), {5, 15}, {35, 15});
  absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 4, StopToken());
  ASSERT_TRUE(seeds.ok()) << seeds.status();
  ASSERT_EQ(seeds->size(), 2u) << "above and below the block";
  ExpectValidSeeds(problem, *seeds);
  auto above = [](const Path& p) {
    for (const Point3& q : p) {
      if (q.y() > 17) return true;  // start and goal are at y = 15
    }
    return false;
  };
  EXPECT_NE(above((*seeds)[0].path), above((*seeds)[1].path)) << "one above, one below";
}

TEST(SeedPathsTest, KeepsTheClearance) {
  Problem problem = ProblemOn(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5});
  problem.clearance = 0.75;
  absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 3, StopToken());
  ASSERT_TRUE(seeds.ok()) << seeds.status();
  ASSERT_EQ(seeds->size(), 2u);
  for (const SeedPath& seed : *seeds) {
    EXPECT_GE(Clearance(*problem.map, seed.path), problem.clearance - 1e-9);
  }
}

TEST(SeedPathsTest, NoPathGivesNoSeedAndCountsAreBounded) {
  std::vector<int8_t> cells(20 * 20, OccupancyGrid::kFree);
  for (int x = 0; x < 20; ++x) cells[10 * 20 + x] = OccupancyGrid::kOccupied;
  const MapPtr walled =
      std::make_shared<const Map>(Map::Data(*OccupancyGrid::Create(20, 20, std::move(cells))));
  const Problem problem = ProblemOn(walled, {5.5, 5.5}, {5.5, 15.5});
  absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 3, StopToken());
  ASSERT_TRUE(seeds.ok()) << seeds.status();
  EXPECT_TRUE(seeds->empty());
  EXPECT_EQ(FindSeedPaths(problem, 0, StopToken()).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(FindSeedPaths(problem, kMaxSeedPaths + 1, StopToken()).status().code(),
            absl::StatusCode::kInvalidArgument);
}

TEST(SeedPathsTest, DistinctCorridorsOnMovingAiMaps) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/Berlin_0_256.map");
  const std::string dir = ::swarmplan::testing::BenchmarksDir() + "/movingai/";
  for (const char* name : {"Berlin_0_256", "8room_000", "AcrosstheCape"}) {
    SCOPED_TRACE(name);
    const std::string file = dir + name + ".map";
    if (!std::filesystem::exists(file)) continue;
    absl::StatusOr<Map> loaded = LoadMapFile(file);
    ASSERT_TRUE(loaded.ok()) << loaded.status();
    const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
    absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(file + ".scen");
    ASSERT_TRUE(scenarios.ok()) << scenarios.status();
    const Scenario& s = scenarios->back();  // the longest bucket
    const OccupancyGrid& grid = *map->grid();
    const Problem problem = ProblemOn(map, grid.CellCenter(s.start), grid.CellCenter(s.goal));
    absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 3, StopToken());
    ASSERT_TRUE(seeds.ok()) << seeds.status();
    ASSERT_EQ(seeds->size(), 3u);
    ExpectValidSeeds(problem, *seeds);
    // Distinct corridors: each later seed leaves the earlier ones somewhere by several cells.
    for (size_t i = 1; i < seeds->size(); ++i) {
      for (size_t j = 0; j < i; ++j) {
        double farthest = 0;
        for (const Point3& p : (*seeds)[i].path) {
          double nearest = 1e18;
          const Path& other = (*seeds)[j].path;
          for (size_t q = 0; q + 1 < other.size(); ++q) {
            nearest =
                std::min(nearest, contract::PointSegmentDistance(p.head<2>(), other[q].head<2>(),
                                                                 other[q + 1].head<2>()));
          }
          farthest = std::max(farthest, nearest);
        }
        EXPECT_GT(farthest, 2.0) << "seed " << i << " follows seed " << j;
      }
    }
  }
}

}  // namespace
}  // namespace swarmplan
