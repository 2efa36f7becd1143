#include "core/algorithms/exact/exact_planners.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_join.h"
#include "core/map/io/map_io.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

constexpr double kSqrt2 = 1.41421356237309504880;

class CountingObserver final : public Observer {
 public:
  void OnIteration(const IterationStats& stats) override { seen.push_back(stats); }
  std::vector<IterationStats> seen;
};

MapPtr AsciiMap(const std::vector<std::string>& rows) {
  absl::StatusOr<Map> map = ParseMap("ascii", {{"test.txt", absl::StrJoin(rows, "\n")}});
  EXPECT_TRUE(map.ok()) << map.status();
  return std::make_shared<const Map>(*std::move(map));
}

// A 10 x 10 world with one 2 x 6 block in the middle.
MapPtr BlockWorld() {
  Polygon block{{Point2(4, 2), Point2(6, 2), Point2(6, 8), Point2(4, 8)}};
  absl::StatusOr<ShapeWorld> world =
      ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(10, 10)}, {}, {block});
  EXPECT_TRUE(world.ok()) << world.status();
  return std::make_shared<const Map>(Map::Data(*std::move(world)));
}

// Rows 0..4; the wall at x = 3 leaves rows 0 and 4 open.
const std::vector<std::string> kWallRows = {
    ".......", "...#...", "...#...", "...#...", ".......",
};

PlanRequest GridRequest(const std::string& algorithm, MapPtr map, Point2 start, Point2 goal) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.problem.map = std::move(map);
  request.problem.start = Point3(start.x(), start.y(), 0);
  request.problem.goal = Point3(goal.x(), goal.y(), 0);
  request.problem.seed = 1;
  return request;
}

TEST(ExactPlannersTest, RegisteredInTheDefaultRegistry) {
  const Registry& registry = DefaultRegistry();
  for (const char* id : {"astar", "dijkstra", "theta-star", "visibility-graph"}) {
    const PlannerInfo* info = registry.Find(id);
    ASSERT_NE(info, nullptr) << id;
    EXPECT_FALSE(info->description.empty());
    EXPECT_FALSE(info->seed_paper.empty());
    EXPECT_EQ(info->encoding, Encoding::kExact);
  }
  EXPECT_TRUE(registry.Find("astar")->Supports(MapKind::kOccupancyGrid));
  EXPECT_FALSE(registry.Find("astar")->Supports(MapKind::kShapeWorld));
  EXPECT_TRUE(registry.Find("visibility-graph")->Supports(MapKind::kShapeWorld));
}

TEST(ExactPlannersTest, AStarReturnsAValidOptimalPath) {
  CountingObserver observer;
  const PlanRequest request = GridRequest("astar", AsciiMap(kWallRows), {0.5, 2.5}, {6.5, 2.5});
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->found);
  EXPECT_TRUE(result->raw_metrics.collision_free);
  EXPECT_NEAR(result->raw_metrics.length, 2 + 4 * kSqrt2, 1e-9);
  EXPECT_NEAR(result->fitness, 2 + 4 * kSqrt2, 1e-9);
  EXPECT_EQ(result->raw_path.front(), Point3(0.5, 2.5, 0));
  EXPECT_EQ(result->raw_path.back(), Point3(6.5, 2.5, 0));
  for (size_t i = 1; i < result->raw_path.size(); ++i) {
    const Point3 step = result->raw_path[i] - result->raw_path[i - 1];
    EXPECT_EQ(std::max(std::abs(step.x()), std::abs(step.y())), 1.0);
  }
  EXPECT_EQ(result->iterations, 1);
  ASSERT_EQ(observer.seen.size(), 1u);
  EXPECT_EQ(observer.seen[0].iteration, 0);
  EXPECT_EQ(observer.seen[0].best_fitness, result->fitness);
  EXPECT_EQ(observer.seen[0].mean_fitness, result->fitness);
  EXPECT_TRUE(observer.seen[0].feasible);
  EXPECT_GT(observer.seen[0].evaluations, 0);
  EXPECT_EQ(result->convergence.size(), 1u);
}

TEST(ExactPlannersTest, GridPlannersAgree) {
  const MapPtr map = AsciiMap(kWallRows);
  NullObserver observer;
  auto length = [&](const std::string& id, ParamValues params = {}) {
    PlanRequest request = GridRequest(id, map, {0.5, 2.5}, {6.5, 2.5});
    request.params = std::move(params);
    absl::StatusOr<PlanResult> r = RunPlan(DefaultRegistry(), request, StopToken(), observer);
    EXPECT_TRUE(r.ok()) << r.status();
    EXPECT_TRUE(r->found) << id;
    EXPECT_TRUE(r->raw_metrics.collision_free) << id;
    return r->raw_metrics.length;
  };
  const double astar = length("astar");
  EXPECT_NEAR(length("dijkstra"), astar, 1e-9);
  EXPECT_NEAR(length("astar", {{"connectivity", std::string("4")}}), 10.0, 1e-9);
  EXPECT_NEAR(length("dijkstra", {{"connectivity", std::string("4")}}), 10.0, 1e-9);
  const double theta = length("theta-star");
  EXPECT_LT(theta, astar);
  EXPECT_GE(theta, 6.0);
}

TEST(ExactPlannersTest, ExactEndpointsOffTheCellCentres) {
  NullObserver observer;
  const PlanRequest request = GridRequest("astar", AsciiMap(kWallRows), {0.2, 2.7}, {6.9, 2.1});
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->found);
  EXPECT_EQ(result->raw_path.front(), Point3(0.2, 2.7, 0));
  EXPECT_EQ(result->raw_path[1], Point3(0.5, 2.5, 0));
  EXPECT_EQ(result->raw_path.back(), Point3(6.9, 2.1, 0));
  EXPECT_TRUE(result->raw_metrics.collision_free);
}

TEST(ExactPlannersTest, UnreachableGoalIsNotAnError) {
  NullObserver observer;
  const PlanRequest request = GridRequest(
      "astar", AsciiMap({".....", ".###.", ".#.#.", ".###.", "....."}), {0.5, 0.5}, {2.5, 2.5});
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->found);
  EXPECT_TRUE(result->raw_path.empty());
}

TEST(ExactPlannersTest, StoppedBeforeRunning) {
  StopToken stop;
  stop.Cancel();
  NullObserver observer;
  const PlanRequest request = GridRequest("astar", AsciiMap(kWallRows), {0.5, 2.5}, {6.5, 2.5});
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, stop, observer);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->found);
  EXPECT_EQ(result->stop_reason, StopReason::kCancelled);
}

TEST(ExactPlannersTest, RejectsUnknownAndWrongParameters) {
  NullObserver observer;
  PlanRequest request = GridRequest("astar", AsciiMap(kWallRows), {0.5, 2.5}, {6.5, 2.5});
  request.params = {{"neighbours", int64_t{8}}};
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_EQ(result.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("neighbours"), std::string::npos);

  request.params = {{"connectivity", std::string("6")}};
  result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_EQ(result.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("connectivity"), std::string::npos);
}

TEST(ExactPlannersTest, MapKindMismatchListsAcceptedKinds) {
  NullObserver observer;
  absl::StatusOr<PlanResult> result = RunPlan(
      DefaultRegistry(), GridRequest("astar", BlockWorld(), {1, 5}, {9, 5}), StopToken(), observer);
  ASSERT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(result.status().message().find("occupancy-grid"), std::string::npos) << result.status();

  result = RunPlan(DefaultRegistry(),
                   GridRequest("visibility-graph", AsciiMap(kWallRows), {0.5, 2.5}, {6.5, 2.5}),
                   StopToken(), observer);
  ASSERT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(result.status().message().find("shape-world"), std::string::npos) << result.status();
}

TEST(ExactPlannersTest, StartInObstacleIsRejected) {
  NullObserver observer;
  absl::StatusOr<PlanResult> result =
      RunPlan(DefaultRegistry(), GridRequest("astar", AsciiMap(kWallRows), {3.5, 2.5}, {6.5, 2.5}),
              StopToken(), observer);
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition) << result.status();
}

TEST(ExactPlannersTest, VisibilityGraphFindsTheEuclideanOptimum) {
  CountingObserver observer;
  absl::StatusOr<PlanResult> result =
      RunPlan(DefaultRegistry(), GridRequest("visibility-graph", BlockWorld(), {1, 5}, {9, 5}),
              StopToken(), observer);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->found);
  EXPECT_TRUE(result->raw_metrics.collision_free);
  // Over the block's top or bottom edge: two diagonals of 3 x 3 and the 2-long edge.
  EXPECT_NEAR(result->raw_metrics.length, 2 + 2 * std::sqrt(18.0), 1e-9);
  EXPECT_EQ(observer.seen.size(), 1u);
}

}  // namespace
}  // namespace swarmplan
