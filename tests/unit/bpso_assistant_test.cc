// The double structure's assistant positions: the optional bound and the trace that shows how
// many of them saturate the sigmoid.

#include <cmath>

#include "core/algorithms/bpso/binary_pso.h"
#include "core/geometry/collision.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

Polygon Square(double x0, double y0, double size) {
  return Polygon{
      {Point2(x0, y0), Point2(x0 + size, y0), Point2(x0 + size, y0 + size), Point2(x0, y0 + size)}};
}

// Three squares: 12 vertices.
Problem ThreeSquares() {
  absl::StatusOr<ShapeWorld> world =
      ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(100, 100)}, {},
                         {Square(20, 15, 20), Square(45, 45, 15), Square(65, 20, 15)});
  EXPECT_TRUE(world.ok());
  Problem p;
  p.map = std::make_shared<const Map>(*world);
  p.start = Point3(2, 2, 0);
  p.goal = Point3(98, 95, 0);
  p.seed = 11;
  return p;
}

struct Traced {
  SearchResult result;
  AssistantTrace trace;
};

Traced SolveTraced(double assistant_bound) {
  BinaryPsoParams params;
  params.assistant_bound = assistant_bound;
  BinaryPsoPlanner planner(params);
  Traced out;
  planner.TraceAssistants(&out.trace);
  NullObserver observer;
  absl::StatusOr<SearchResult> result = planner.Solve(ThreeSquares(), StopToken(), observer);
  EXPECT_TRUE(result.ok()) << result.status();
  if (result.ok()) out.result = *std::move(result);
  return out;
}

TEST(BpsoAssistantTest, TraceHasOneEntryPerIteration) {
  const Traced unbounded = SolveTraced(0.0);
  ASSERT_EQ(unbounded.trace.saturated_fraction.size(),
            static_cast<size_t>(unbounded.result.iterations));
  ASSERT_EQ(unbounded.trace.mean_magnitude.size(),
            static_cast<size_t>(unbounded.result.iterations));
  for (double f : unbounded.trace.saturated_fraction) {
    EXPECT_GE(f, 0.0);
    EXPECT_LE(f, 1.0);
  }
  // Unbounded, the positions drift past the sigmoid's saturation by the last iteration.
  EXPECT_GT(unbounded.trace.saturated_fraction.back(), 0.0);
  EXPECT_GT(unbounded.trace.mean_magnitude.back(), 1.0);
}

TEST(BpsoAssistantTest, BoundKeepsEveryPositionInside) {
  const Traced bounded = SolveTraced(1.0);
  ASSERT_FALSE(bounded.trace.mean_magnitude.empty());
  for (size_t t = 0; t < bounded.trace.mean_magnitude.size(); ++t) {
    EXPECT_LE(bounded.trace.mean_magnitude[t], 1.0 + 1e-12) << t;
    EXPECT_EQ(bounded.trace.saturated_fraction[t], 0.0) << t;
  }
  ASSERT_TRUE(bounded.result.found);
  const Problem problem = ThreeSquares();
  EXPECT_EQ(bounded.result.path.front(), problem.start);
  EXPECT_EQ(bounded.result.path.back(), problem.goal);
  EXPECT_TRUE(MakeCollisionChecker(*problem.map)->PathFree(bounded.result.path, 0.0));
}

TEST(BpsoAssistantTest, TracingChangesNoResult) {
  BinaryPsoPlanner plain{BinaryPsoParams{}};
  NullObserver observer;
  absl::StatusOr<SearchResult> untraced = plain.Solve(ThreeSquares(), StopToken(), observer);
  ASSERT_TRUE(untraced.ok());
  const Traced traced = SolveTraced(0.0);
  EXPECT_EQ(untraced->path, traced.result.path);
  EXPECT_EQ(untraced->fitness, traced.result.fitness);
}

}  // namespace
}  // namespace swarmplan
