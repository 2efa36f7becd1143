// Requests a planner cannot serve are rejected by ValidatePlanRequest, before planning, and
// requests it accepts do not fail later for a reason known up front.

#include <memory>
#include <string>

#include "absl/status/status.h"
#include "core/geometry/collision.h"
#include "core/registry.h"
#include "core/run.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

// 20 x 10 with a block over [10.3, 12] x [0, 6]: the goal (10, 3) keeps 0.3 from it, but the
// 1-unit raster cell (10, 3) = [10, 11] x [3, 4] overlaps the block.
MapPtr BlockWorld() {
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(
      Bounds2{Point2(0, 0), Point2(20, 10)}, {},
      {Polygon{{Point2(10.3, 0), Point2(12, 0), Point2(12, 6), Point2(10.3, 6)}}});
  EXPECT_TRUE(world.ok()) << world.status();
  return std::make_shared<const Map>(*std::move(world));
}

PlanRequest Request(const std::string& algorithm, const MapPtr& map, Point3 start, Point3 goal) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.problem.map = map;
  request.problem.start = start;
  request.problem.goal = goal;
  request.problem.seed = 5;
  request.problem.limits.max_iterations = 30;
  return request;
}

TEST(PlanPreconditionsTest, GoalNearAPolygonIsPlannedOnTheAutomaticRaster) {
  const PlanRequest request = Request("as-bfo", BlockWorld(), Point3(2, 8, 0), Point3(10, 3, 0));
  ASSERT_NEAR(MakeCollisionChecker(*request.problem.map)->Clearance(request.problem.goal), 0.3,
              1e-12);
  ASSERT_TRUE(ValidatePlanRequest(DefaultRegistry(), request).ok());
  NullObserver observer;
  absl::StatusOr<PlanResult> r = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_TRUE(r.ok()) << r.status();
  ASSERT_TRUE(r->found);
  EXPECT_EQ(r->raw_path.front(), request.problem.start);
  EXPECT_EQ(r->raw_path.back(), request.problem.goal);
  EXPECT_TRUE(r->raw_metrics.collision_free);
}

TEST(PlanPreconditionsTest, CoarseRasterCellIsRejectedNamingPlannerAndCell) {
  PlanRequest request = Request("as-bfo", BlockWorld(), Point3(2, 8, 0), Point3(10, 3, 0));
  request.params["resolution"] = 1.0;
  const absl::Status status = ValidatePlanRequest(DefaultRegistry(), request);
  EXPECT_EQ(status.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_THAT(status.message(),
              AllOf(HasSubstr("'as-bfo'"), HasSubstr("goal (10, 3)"), HasSubstr("cell (10, 3)")));
  NullObserver observer;
  EXPECT_EQ(RunPlan(DefaultRegistry(), request, StopToken(), observer).status().code(),
            absl::StatusCode::kFailedPrecondition);
}

// A goal that keeps the clearance by 1e-9 only: no raster within the cell bound has a usable
// cell there.
TEST(PlanPreconditionsTest, PointNoRasterCanUseIsRejected) {
  PlanRequest request = Request("ga", BlockWorld(), Point3(2, 8, 0), Point3(9.8 - 1e-9, 3, 0));
  request.problem.clearance = 0.5;
  const absl::Status status = ValidatePlanRequest(DefaultRegistry(), request);
  EXPECT_EQ(status.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_THAT(status.message(), AllOf(HasSubstr("'ga'"), HasSubstr("goal"), HasSubstr("cell (")));
}

// On an occupancy grid the raster is the map: a start that keeps the clearance in a cell whose
// centre does not is rejected by the grid planners and the exact grid searches alike.
TEST(PlanPreconditionsTest, UnusableGridCellIsRejectedByEveryGridPlanner) {
  const MapPtr map = ::swarmplan::testing::GridMap({
      "..........",  //
      "..........",  //
      "..........",  //
      "..........",  //
      "..........",  //
      ".....#....",  //
      "..........",  //
      "..........",  //
  });
  for (const std::string id : {"as-bfo", "aco-grid", "astar", "theta-star"}) {
    PlanRequest request = Request(id, map, Point3(4.2, 5.5, 0), Point3(9.5, 0.5, 0));
    request.problem.clearance = 0.6;  // the start keeps 0.8, its cell's centre 0.5
    const absl::Status status = ValidatePlanRequest(DefaultRegistry(), request);
    EXPECT_EQ(status.code(), absl::StatusCode::kFailedPrecondition) << id;
    EXPECT_THAT(status.message(),
                AllOf(HasSubstr("'" + id + "'"), HasSubstr("start"), HasSubstr("cell (4, 5)")))
        << id;
  }
}

}  // namespace
}  // namespace swarmplan
