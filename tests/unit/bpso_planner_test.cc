#include <cmath>

#include "core/algorithms/bpso/binary_pso.h"
#include "core/geometry/collision.h"
#include "core/graph/visibility_graph.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

using namespace swarmplan::testing;

Polygon Square(double x0, double y0, double size) {
  return Polygon{
      {Point2(x0, y0), Point2(x0 + size, y0), Point2(x0 + size, y0 + size), Point2(x0, y0 + size)}};
}

// Four square obstacles: 16 vertices, as in the paper's second environment size.
Problem FourSquares(uint64_t seed = 3) {
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(
      Bounds2{Point2(0, 0), Point2(100, 100)}, {},
      {Square(20, 10, 20), Square(25, 55, 15), Square(60, 30, 20), Square(55, 70, 15)});
  EXPECT_TRUE(world.ok());
  Problem p;
  p.map = std::make_shared<const Map>(*world);
  p.start = Point3(2, 2, 0);
  p.goal = Point3(98, 95, 0);
  p.seed = seed;
  return p;
}

double Optimum(const Problem& p) {
  absl::StatusOr<Path> path =
      ShortestPathVisibility(*p.map->world(), Point2(p.start.x(), p.start.y()),
                             Point2(p.goal.x(), p.goal.y()), p.clearance, 0.01);
  EXPECT_TRUE(path.ok()) << path.status();
  return path.ok() ? PathLength(*path) : 0.0;
}

TEST(BinaryPsoTest, FindsACollisionFreePathNearTheOptimum) {
  const Problem problem = FourSquares();
  BinaryPsoPlanner planner{BinaryPsoParams{}};
  RecordingObserver observer;
  absl::StatusOr<SearchResult> r = planner.Solve(problem, StopToken(), observer);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE(r->found);
  EXPECT_EQ(r->path.front(), problem.start);
  EXPECT_EQ(r->path.back(), problem.goal);
  EXPECT_TRUE(MakeCollisionChecker(*problem.map)->PathFree(r->path, 0.0));
  EXPECT_NEAR(r->fitness, PathLength(r->path), 1e-9);
  EXPECT_LE(r->fitness, 1.1 * Optimum(problem));  // stated factor: within 10% of the optimum
  EXPECT_EQ(r->iterations, 100);
  ExpectMonotoneLog(observer.stats, r->iterations);
}

TEST(BinaryPsoTest, KeepsTheClearance) {
  Problem problem = FourSquares(8);
  problem.clearance = 1.0;
  // Grown corners are arcs: a coarse polygonisation keeps the vertex count (and the search
  // space, which grows as 2^vertices) small.
  BinaryPsoParams params;
  params.circle_tolerance = 0.05;
  BinaryPsoPlanner planner{params};
  NullObserver none;
  const SearchResult r = *planner.Solve(problem, StopToken(), none);
  EXPECT_TRUE(r.found);
  EXPECT_GE(MakeCollisionChecker(*problem.map)->PathClearance(r.path), 1.0 - 1e-6);
  EXPECT_LE(r.fitness, 1.2 * Optimum(problem));
}

TEST(BinaryPsoTest, PlainBpsoRunsToo) {
  const Problem problem = FourSquares();
  BinaryPsoParams params;
  params.double_structure = false;
  params.mutation_probability = 0.0;
  BinaryPsoPlanner planner{params};
  NullObserver none;
  const SearchResult r = *planner.Solve(problem, StopToken(), none);
  EXPECT_EQ(r.path.front(), problem.start);
  EXPECT_EQ(r.path.back(), problem.goal);
  EXPECT_EQ(r.found, MakeCollisionChecker(*problem.map)->PathFree(r.path, 0.0));
}

TEST(BinaryPsoTest, SameSeedSamePath) {
  BinaryPsoPlanner a{BinaryPsoParams{}}, b{BinaryPsoParams{}};
  NullObserver none;
  const SearchResult ra = *a.Solve(FourSquares(21), StopToken(), none);
  const SearchResult rb = *b.Solve(FourSquares(21), StopToken(), none);
  EXPECT_EQ(ra.path, rb.path);
  EXPECT_EQ(ra.fitness, rb.fitness);
}

TEST(BinaryPsoTest, StopsWithinOneIterationOfACancel) {
  BinaryPsoPlanner planner{BinaryPsoParams{}};
  StopToken stop;
  CancellingObserver observer(stop, 0);
  const SearchResult r = *planner.Solve(FourSquares(), stop, observer);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_EQ(r.stop_reason, StopReason::kCancelled);
}

TEST(BinaryPsoTest, PlansOnGridsThroughBlockedCorners) {
  const MapPtr map = GridMap(TwoWallsRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{11, 11});
  BinaryPsoPlanner planner{BinaryPsoParams{}};
  NullObserver none;
  const SearchResult r = *planner.Solve(problem, StopToken(), none);
  EXPECT_TRUE(r.found);
  EXPECT_TRUE(MakeCollisionChecker(*map)->PathFree(r.path, 0.0));
  EXPECT_LE(r.fitness, AStarLength(*map->grid(), Cell{0, 0}, Cell{11, 11}) + 1e-9);
}

TEST(BinaryPsoTest, RefusesMapsWithTooManyVertices) {
  BinaryPsoParams params;
  params.max_vertices = 8;
  BinaryPsoPlanner planner{params};
  NullObserver none;
  EXPECT_EQ(planner.Solve(FourSquares(), StopToken(), none).status().code(),
            absl::StatusCode::kFailedPrecondition);
}

TEST(BinaryPsoTest, IsRegistered) {
  Registry registry;
  ASSERT_TRUE(registry.Register(BinaryPsoInfo()).ok());
  EXPECT_TRUE(registry.Create("bpso", {{"mutation_probability", 0.0}}).ok());
}

}  // namespace
}  // namespace swarmplan
