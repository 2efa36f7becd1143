#include "bench/papers/idafsa_grids_replicated.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bench/papers/experiments.h"
#include "bench/papers/idafsa_grids_worlds.h"
#include "core/map/io/map_writers.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

std::string ShippedText(const IdafsaGridWorld& world) {
  std::ifstream in(std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds/idafsa-grids/" + world.file,
                   std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

ExperimentOptions QuickOptions() {
  ExperimentOptions options;
  options.quick = true;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  return options;
}

TEST(IdafsaGridsReplicatedTest, WorldZeroIsTheShippedWorld) {
  for (const IdafsaGridWorld& shipped : IdafsaGridWorlds()) {
    const IdafsaGridWorld world = ReplicatedIdafsaWorld(shipped, 0);
    EXPECT_EQ(world.seed, shipped.seed);
    EXPECT_EQ(world.file, shipped.file);
    absl::StatusOr<DrawnIdafsaGrid> drawn = DrawIdafsaGrid(world);
    ASSERT_TRUE(drawn.ok()) << drawn.status();
    EXPECT_EQ(FormatAsciiMap(drawn->grid), ShippedText(shipped)) << shipped.file;
  }
}

TEST(IdafsaGridsReplicatedTest, WorldsAreDeterministicDistinctAndConnected) {
  for (const IdafsaGridWorld& shipped : IdafsaGridWorlds()) {
    std::set<std::string> layouts;
    for (int r = 0; r < kReplicatedWorlds; ++r) {
      const IdafsaGridWorld world = ReplicatedIdafsaWorld(shipped, r);
      EXPECT_EQ(world.seed, shipped.seed + r * kWorldSeedStride);
      absl::StatusOr<DrawnIdafsaGrid> a = DrawIdafsaGrid(world);
      absl::StatusOr<DrawnIdafsaGrid> b = DrawIdafsaGrid(world);
      ASSERT_TRUE(a.ok()) << a.status();
      ASSERT_TRUE(b.ok()) << b.status();
      EXPECT_EQ(FormatAsciiMap(a->grid), FormatAsciiMap(b->grid)) << world.file;
      EXPECT_EQ(a->seed, b->seed);
      EXPECT_GE(a->seed, world.seed);
      EXPECT_LT(a->seed, world.seed + kWorldSeedStride);
      EXPECT_EQ(a->grid.width(), shipped.size);
      EXPECT_EQ(a->grid.BlockedCount(),
                std::llround(shipped.obstacle_ratio * shipped.size * shipped.size));
      EXPECT_TRUE(FourConnected(a->grid, IdafsaStart(world), IdafsaGoal(world))) << world.file;
      layouts.insert(FormatAsciiMap(a->grid));
    }
    EXPECT_EQ(layouts.size(), static_cast<size_t>(kReplicatedWorlds)) << shipped.file;
  }
}

TEST(IdafsaGridsReplicatedTest, RunsRecordEachWorldsOptimum) {
  const IdafsaGridWorld& shipped = IdafsaGridWorlds().front();
  const std::vector<FishConfig> configs = {{"dafsa", "dafsa", {}}, {"idafsa", "idafsa", {}}};
  absl::StatusOr<ReplicatedIdafsaGrid> grid =
      RunReplicatedIdafsaGrid(shipped, configs, QuickOptions(), /*worlds=*/2, /*runs=*/2,
                              /*generations=*/10);
  ASSERT_TRUE(grid.ok()) << grid.status();
  ASSERT_EQ(grid->worlds.size(), 2u);
  // The shipped 10 x 10 world's optimum and Theta* length, as its report gives them.
  EXPECT_NEAR(grid->worlds[0].optimum, 13.7727, 1e-4);
  EXPECT_NEAR(grid->worlds[0].theta_star, 13.5952, 1e-4);
  EXPECT_EQ(grid->worlds[0].seed_drawn, 3001u);
  for (const ReplicatedIdafsaWorldRuns& world : grid->worlds) {
    absl::StatusOr<DrawnIdafsaGrid> drawn = DrawIdafsaGrid(world.spec);
    ASSERT_TRUE(drawn.ok());
    EXPECT_EQ(world.seed_drawn, drawn->seed);
    EXPECT_EQ(world.blocked, static_cast<int>(drawn->grid.BlockedCount()));
    EXPECT_DOUBLE_EQ(world.optimum,
                     *MoveSetOptimum(drawn->grid, Neighbourhood::k24, IdafsaStart(world.spec),
                                     IdafsaGoal(world.spec)));
    EXPECT_LE(world.theta_star, world.optimum + 1e-9);
    ASSERT_EQ(world.configs.size(), configs.size());
    for (const FishRunStats& stats : world.configs) {
      EXPECT_EQ(stats.runs, 2);
      for (double length : stats.lengths) {
        EXPECT_GE(length, world.optimum - 1e-9);
      }
    }
  }
}

TEST(IdafsaGridsReplicatedTest, QuickReportHasTheSignificanceAndReplicationSections) {
  absl::StatusOr<std::string> report = RunIdafsaGrids(QuickOptions());
  ASSERT_TRUE(report.ok()) << report.status();
  for (const char* expected :
       {"### idafsa against the other configurations on 10 x 10",
        "### idafsa against the other configurations on 20 x 20",
        "## Replication: drawn worlds per grid size", "### 10 x 10: 2 worlds",
        "### 20 x 20: 2 worlds", "signed-rank p (length / optimum)", "Fisher p", "| 1 | 4001 |",
        "- **2 worlds of 10 x 10**", "- **2 worlds of 20 x 20**", "The paper's headline"}) {
    EXPECT_NE(report->find(expected), std::string::npos) << expected;
  }
}

}  // namespace
}  // namespace swarmplan::bench
