// Plans through via-points (core/via_points): the path passes through each via-point in order,
// joins the requested start and goal exactly, is collision-free by an independent check, its
// length is the sum of its legs' and at least the sum of the legs' exact optima; the same seed
// gives the same path; bad via-points are refused naming the field; a leg without a path ends
// the plan at the last via-point reached.

#include "core/via_points.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/geometry/collision.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"
#include "tests/unit/plan_test_support.h"

namespace swarmplan {
namespace {

// 12 x 12 with two walls; (0.5, 11.5) -> (11.5, 0.5) passes one via-point on the far side.
PlanRequest TwoWallsRequest(const std::string& algorithm) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.problem =
      testing::GridProblemFor(testing::GridMap(testing::TwoWallsRows()), {0, 11}, {11, 0}, 3);
  request.via_points = {Point3(10.5, 10.5, 0), Point3(1.5, 1.5, 0)};
  request.problem.limits.max_iterations = 30;
  return request;
}

bool Contains(const Path& path, const Point3& p) {
  return std::find(path.begin(), path.end(), p) != path.end();
}

absl::StatusOr<PlanResult> Plan(const PlanRequest& request) {
  testing::NullObserver observer;
  return RunPlan(DefaultRegistry(), request, StopToken(), observer);
}

TEST(ViaPointsTest, ThePathPassesEachViaPointInOrder) {
  for (const std::string algorithm : {"theta-star", "pso"}) {
    SCOPED_TRACE(algorithm);
    const PlanRequest request = TwoWallsRequest(algorithm);
    absl::StatusOr<PlanResult> result = Plan(request);
    ASSERT_TRUE(result.ok()) << result.status();
    ASSERT_TRUE(result->found);
    const Path& path = result->raw_path;
    EXPECT_EQ(path.front(), request.problem.start);
    EXPECT_EQ(path.back(), request.problem.goal);
    const auto first = std::find(path.begin(), path.end(), request.via_points[0]);
    const auto second = std::find(path.begin(), path.end(), request.via_points[1]);
    ASSERT_NE(first, path.end());
    ASSERT_NE(second, path.end());
    EXPECT_LT(first, second) << "in order";
    EXPECT_TRUE(MakeCollisionChecker(*request.problem.map)->PathFree(path, 0.0));
    EXPECT_EQ(result->via_points_reached, 2);
    ASSERT_EQ(result->legs.size(), 3u);
    double legs = 0.0;
    for (const PlanResult::Leg& leg : result->legs) {
      EXPECT_TRUE(leg.found);
      legs += leg.metrics.length;
    }
    EXPECT_NEAR(PathLength(path), legs, 1e-9);
    // No shorter than the legs' exact optima.
    std::vector<Optimum> optima;
    for (const Problem& leg : LegProblems(request)) {
      optima.push_back(ComputeOptimum(DefaultRegistry(), leg, absl::Seconds(10)));
    }
    const Optimum through = CombineLegOptima(optima);
    ASSERT_TRUE(through.known) << through.reason;
    EXPECT_GE(PathLength(path), through.length * (1 - 1e-9));
    EXPECT_LE(PathLength(path), through.length * 1.1);
    // One convergence, iterations counted on across the legs.
    for (size_t i = 1; i < result->convergence.size(); ++i) {
      EXPECT_GT(result->convergence[i].iteration, result->convergence[i - 1].iteration);
    }
  }
}

TEST(ViaPointsTest, SameSeedSamePath) {
  PlanRequest request = TwoWallsRequest("pso");
  absl::StatusOr<PlanResult> a = Plan(request);
  absl::StatusOr<PlanResult> b = Plan(request);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->raw_path, b->raw_path);
  EXPECT_EQ(a->fitness, b->fitness);
  EXPECT_EQ(a->seed, 3u);
}

TEST(ViaPointsTest, BadViaPointsAreRefusedNamingTheField) {
  PlanRequest request = TwoWallsRequest("theta-star");
  request.via_points[1] = Point3(3.5, 5.5, 0);  // inside the left wall
  absl::StatusOr<PlanResult> blocked = Plan(request);
  EXPECT_EQ(blocked.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(blocked.status().message().find("via_points[1]"), std::string::npos)
      << blocked.status();
  request.via_points.assign(kMaxViaPoints + 1, Point3(1.5, 1.5, 0));
  absl::StatusOr<PlanResult> many = Plan(request);
  EXPECT_EQ(many.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(many.status().message().find("via_points"), std::string::npos) << many.status();
}

TEST(ViaPointsTest, ALegWithoutAPathEndsThePlanAtTheLastViaPointReached) {
  // The right column is walled off: the second via-point can be reached from nowhere.
  std::vector<std::string> rows(8, "....#...");
  const MapPtr map = testing::GridMap(rows);
  PlanRequest request;
  request.algorithm = "theta-star";
  request.problem = testing::GridProblemFor(map, {0, 0}, {0, 7});
  request.via_points = {Point3(3.5, 3.5, 0), Point3(6.5, 3.5, 0)};
  absl::StatusOr<PlanResult> result = Plan(request);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->found);
  EXPECT_EQ(result->via_points_reached, 1);
  ASSERT_EQ(result->legs.size(), 2u);
  EXPECT_TRUE(result->legs[0].found);
  EXPECT_FALSE(result->legs[1].found);
  ASSERT_FALSE(result->raw_path.empty());
  EXPECT_EQ(result->raw_path.front(), request.problem.start);
  EXPECT_EQ(result->raw_path.back(), request.via_points[0]);
  EXPECT_TRUE(Contains(result->raw_path, request.via_points[0]));
}

}  // namespace
}  // namespace swarmplan
