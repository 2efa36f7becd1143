// The deterministic parts of the bas-canyon reproduction: the generated canyons and the lattice
// yardstick of the shipped one.

#include "bench/papers/bas_canyon_world.h"

#include <set>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "bench/papers/bas_canyon_sweeps.h"
#include "bench/papers/bas_canyon_terrain.h"
#include "bench/papers/world_replication.h"
#include "bench/tests/read_file.h"
#include "core/operators/terrain_path_cost.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"

namespace swarmplan::bench::bas {
namespace {

std::string WorldsDir() { return absl::StrCat(SWARMPLAN_SOURCE_DIR, "/bench/worlds"); }

// The lattice optimum from mouth to mouth at kLatticeVerticalStep, as the run prints it.
constexpr double kPinnedYardstick = 89.729173189020301;

TEST(BasCanyonWorldTest, GeneratedCanyonEqualsTheShippedFile) {
  const std::string shipped = ReadFile(absl::StrCat(WorldsDir(), "/bas-canyon/", kCanyonFile));
  ASSERT_FALSE(shipped.empty());
  EXPECT_EQ(CanyonAscText(kCanyonSeed), shipped);
}

TEST(BasCanyonWorldTest, ReplicatedWorldZeroIsTheShippedCanyonAndTheOthersDiffer) {
  absl::StatusOr<CanyonWorld> shipped =
      LoadShippedCanyon(WorldsDir(), CanyonShape().mouth_y, kQuickLatticeVerticalStep);
  ASSERT_TRUE(shipped.ok()) << shipped.status();
  std::set<std::vector<double>> heights;
  for (int index = 0; index < kReplicatedWorlds; ++index) {
    absl::StatusOr<CanyonWorld> world = DrawCanyonWorld(index, kQuickLatticeVerticalStep);
    ASSERT_TRUE(world.ok()) << world.status();
    EXPECT_EQ(world->seed, kCanyonSeed + static_cast<uint64_t>(index) * kWorldSeedStride);
    heights.insert(world->map->terrain()->heights());
    if (index == 0) {
      EXPECT_EQ(world->map->terrain()->heights(), shipped->map->terrain()->heights());
      EXPECT_EQ(world->start, shipped->start);
      EXPECT_EQ(world->goal, shipped->goal);
      EXPECT_EQ(world->lattice.cost, shipped->lattice.cost);
    }
  }
  EXPECT_EQ(heights.size(), static_cast<size_t>(kReplicatedWorlds));
}

// The yardstick of Table A: its value (pinned; a change to the lattice or the canyon moves
// the committed report), recomputed from its path, the path collision-free and in the deep
// right branch.
TEST(BasCanyonWorldTest, LatticeYardstickOfTheShippedCanyon) {
  absl::StatusOr<CanyonWorld> world =
      LoadShippedCanyon(WorldsDir(), CanyonShape().mouth_y, kLatticeVerticalStep);
  ASSERT_TRUE(world.ok()) << world.status();
  EXPECT_EQ(world->start, Point3(0, 10, 4));
  EXPECT_EQ(world->goal, Point3(20, 10, 4.02));
  EXPECT_NEAR(world->lattice.cost, kPinnedYardstick, 1e-9);
  EXPECT_NEAR(TerrainPathCost(world->lattice.path, 1.0), world->lattice.cost, 1e-9);
  EXPECT_TRUE(EvaluatePath(*world->map, world->lattice.path, 0.0).collision_free);
  EXPECT_TRUE(InRightBranch(world->lattice.path));
}

TEST(BasCanyonWorldTest, MovedStartIsOnTheLeftOfTheMouth) {
  absl::StatusOr<CanyonWorld> world =
      LoadShippedCanyon(WorldsDir(), MovedStartY(), kQuickLatticeVerticalStep);
  ASSERT_TRUE(world.ok()) << world.status();
  EXPECT_EQ(world->start.x(), 0.0);
  EXPECT_EQ(world->start.y(), CanyonShape().mouth_y - CanyonShape().left_bulge);
  EXPECT_DOUBLE_EQ(world->start.z(), world->map->terrain()->GroundAt(Point2(0, MovedStartY())) +
                                         kStartHeightAboveGround);
}

}  // namespace
}  // namespace swarmplan::bench::bas
