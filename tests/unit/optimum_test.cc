#include "core/optimum.h"

#include <memory>

#include "core/map/map.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

MapPtr WallWorld() {
  // A 20 x 10 world with a wall from y = 1 to y = 8 at x in [9, 11]: the path goes under it.
  Polygon wall;
  wall.vertices = {Point2(9, 1), Point2(11, 1), Point2(11, 8), Point2(9, 8)};
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create({Point2(0, 0), Point2(20, 10)}, {}, {wall});
  EXPECT_TRUE(world.ok()) << world.status();
  return std::make_shared<const Map>(*std::move(world));
}

Problem AcrossTheWall(MapPtr map) {
  Problem problem;
  problem.map = std::move(map);
  problem.start = Point3(2, 2, 0);
  problem.goal = Point3(18, 2, 0);
  return problem;
}

TEST(OptimumTest, EachMapKindHasAnExactPlanner) {
  for (MapKind kind : {MapKind::kOccupancyGrid, MapKind::kShapeWorld, MapKind::kTerrain}) {
    const PlannerInfo* info = DefaultRegistry().Find(ExactPlannerFor(kind));
    ASSERT_NE(info, nullptr) << MapKindName(kind);
    EXPECT_EQ(info->encoding, Encoding::kExact);
    EXPECT_TRUE(info->Supports(kind));
  }
}

TEST(OptimumTest, ShapeWorldOptimumIsTheVisibilityGraphLength) {
  const Optimum optimum =
      ComputeOptimum(DefaultRegistry(), AcrossTheWall(WallWorld()), absl::Seconds(10));
  ASSERT_TRUE(optimum.known) << optimum.reason;
  EXPECT_EQ(optimum.planner, "visibility-graph");
  // Under the wall's lower corners (9, 1) and (11, 1).
  const double expected = 2 * std::hypot(7.0, 1.0) + 2.0;
  EXPECT_NEAR(optimum.length, expected, 1e-9);
}

TEST(OptimumTest, SaysWhyWhenItIsNotKnown) {
  const Optimum off =
      ComputeOptimum(DefaultRegistry(), AcrossTheWall(WallWorld()), absl::ZeroDuration());
  EXPECT_FALSE(off.known);
  EXPECT_NE(off.reason.find("budget"), std::string::npos) << off.reason;

  const Registry empty;
  const Optimum missing = ComputeOptimum(empty, AcrossTheWall(WallWorld()), absl::Seconds(1));
  EXPECT_FALSE(missing.known);
  EXPECT_NE(missing.reason.find("visibility-graph"), std::string::npos) << missing.reason;

  // A wall of overlapping circles across the whole world: no path exists.
  std::vector<Circle> wall;
  for (double y = -1; y <= 11; y += 2) wall.push_back({Point2(10, y), 1.5});
  absl::StatusOr<ShapeWorld> closed =
      ShapeWorld::Create({Point2(0, 0), Point2(20, 10)}, std::move(wall), {});
  ASSERT_TRUE(closed.ok()) << closed.status();
  const Optimum none = ComputeOptimum(
      DefaultRegistry(), AcrossTheWall(std::make_shared<const Map>(*std::move(closed))),
      absl::Seconds(10));
  EXPECT_FALSE(none.known);
  EXPECT_FALSE(none.reason.empty());
}

TEST(OptimumTest, RatioMeasuresTheFinalPath) {
  PlanRequest request;
  request.algorithm = "visibility-graph";
  request.problem = AcrossTheWall(WallWorld());
  NullObserver observer;
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, {}, observer);
  ASSERT_TRUE(result.ok()) << result.status();
  const Map& map = *request.problem.map;
  SetOptimum(map, ComputeOptimum(DefaultRegistry(), request.problem, absl::Seconds(10)), *result);
  EXPECT_NEAR(result->optimality_ratio, 1.0, 1e-12);

  Optimum half = result->optimum;
  half.cost *= 0.5;
  SetOptimum(map, half, *result);
  EXPECT_NEAR(result->optimality_ratio, 2.0, 1e-12);
  SetOptimum(map, Optimum{}, *result);
  EXPECT_EQ(result->optimality_ratio, 0.0);
}

}  // namespace
}  // namespace swarmplan
