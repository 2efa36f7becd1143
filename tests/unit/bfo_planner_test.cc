#include <cmath>

#include "core/algorithms/bfo/as_bfo.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

using namespace swarmplan::testing;

TEST(AsBfoTest, FindsAValidPathNearTheOptimum) {
  const MapPtr map = GridMap(TwoWallsRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{11, 11});
  AsBfoPlanner planner{AsBfoParams{}};
  RecordingObserver observer;
  absl::StatusOr<SearchResult> r = planner.Solve(problem, StopToken(), observer);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE(r->found);
  ExpectValidGridPath(*map->grid(), r->path, Cell{0, 0}, Cell{11, 11}, Neighbourhood::k8);
  const double optimum = AStarLength(*map->grid(), Cell{0, 0}, Cell{11, 11});
  EXPECT_NEAR(r->fitness, PathLength(r->path), 1e-9);
  EXPECT_LE(r->fitness, 1.15 * optimum);  // stated factor: within 15% of A*
  EXPECT_GE(r->fitness, optimum - 1e-9);
  EXPECT_EQ(r->iterations, 5 * 2 * 2);  // Nc * Nre * Ned
  ExpectMonotoneLog(observer.stats, r->iterations);
  ExpectMonotoneLog(r->convergence, r->iterations);
  EXPECT_NEAR(r->convergence.back().best_fitness, r->fitness, 1e-12);
  EXPECT_LE(r->best_iteration, r->iterations);
}

TEST(AsBfoTest, SameSeedSamePath) {
  const MapPtr map = GridMap(TwoWallsRows());
  const Problem problem = GridProblemFor(map, Cell{0, 11}, Cell{11, 0}, 42);
  AsBfoParams params;
  params.population = 20;
  AsBfoPlanner a{params}, b{params};
  NullObserver none;
  const SearchResult ra = *a.Solve(problem, StopToken(), none);
  const SearchResult rb = *b.Solve(problem, StopToken(), none);
  EXPECT_EQ(ra.path, rb.path);
  EXPECT_EQ(ra.evaluations, rb.evaluations);
  ExpectValidGridPath(*map->grid(), ra.path, Cell{0, 11}, Cell{11, 0}, Neighbourhood::k8);
}

TEST(AsBfoTest, StopsWithinOneIterationOfACancel) {
  const MapPtr map = GridMap(TwoWallsRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{11, 11});
  AsBfoPlanner planner{AsBfoParams{}};
  StopToken stop;
  CancellingObserver observer(stop, 2);
  const SearchResult r = *planner.Solve(problem, stop, observer);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_EQ(observer.count, 3);
  EXPECT_EQ(r.stop_reason, StopReason::kCancelled);
  EXPECT_TRUE(r.found);  // the best of what it had
}

TEST(AsBfoTest, DisconnectedGoalIsNotFound) {
  const MapPtr map = GridMap({"..#..", "..#..", "..#.."});
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{4, 2});
  AsBfoPlanner planner{AsBfoParams{}};
  NullObserver none;
  const SearchResult r = *planner.Solve(problem, StopToken(), none);
  EXPECT_FALSE(r.found);
  EXPECT_TRUE(r.path.empty());
}

TEST(AsBfoTest, BlockedStartIsAPreconditionError) {
  const MapPtr map = GridMap({"#....", ".....", "....."});
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{4, 2});
  AsBfoPlanner planner{AsBfoParams{}};
  NullObserver none;
  EXPECT_EQ(planner.Solve(problem, StopToken(), none).status().code(),
            absl::StatusCode::kFailedPrecondition);
}

TEST(AsBfoTest, PlansOnARasterisedShapeWorld) {
  absl::StatusOr<ShapeWorld> world =
      ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(10, 10)}, {Circle{Point2(5, 5), 2.0}}, {});
  ASSERT_TRUE(world.ok());
  Problem problem;
  problem.map = std::make_shared<const Map>(*world);
  problem.start = Point3(1.25, 1.25, 0);
  problem.goal = Point3(8.75, 8.75, 0);
  AsBfoParams params;
  params.resolution = 0.5;
  AsBfoPlanner planner{params};
  NullObserver none;
  absl::StatusOr<SearchResult> r = planner.Solve(problem, StopToken(), none);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE(r->found);
  EXPECT_NEAR(r->path.front().x(), 1.25, 1e-9);
  EXPECT_NEAR(r->path.back().y(), 8.75, 1e-9);
  EXPECT_LE(r->fitness, 1.3 * (std::hypot(7.5, 7.5)));
}

TEST(AsBfoTest, IsRegisteredWithThePapersDefaults) {
  Registry registry;
  ASSERT_TRUE(registry.Register(AsBfoInfo()).ok());
  absl::StatusOr<std::unique_ptr<Planner>> planner = registry.Create("as-bfo", {});
  ASSERT_TRUE(planner.ok());
  EXPECT_FALSE(registry.Create("as-bfo", {{"population", int64_t{0}}}).ok());
}

}  // namespace
}  // namespace swarmplan
