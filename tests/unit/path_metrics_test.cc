#include "core/path_metrics.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "gtest/gtest.h"

namespace swarmplan {
namespace {

Point3 P(double x, double y, double z = 0.0) { return Point3(x, y, z); }

Map OpenWorld() {
  return Map(
      *ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(10, 10)}, {Circle{Point2(5, 5), 1.0}}, {}));
}

TEST(PathMetricsTest, RightAngle) {
  const Map map = OpenWorld();
  const Path path = {P(1, 1), P(3, 1), P(3, 3)};
  const PathMetrics m = EvaluatePath(map, path, 0.5);
  EXPECT_DOUBLE_EQ(m.length, 4.0);
  EXPECT_EQ(m.turning_points, 1);
  // The circle through (1,1), (3,1), (3,3) has the hypotenuse as diameter: radius sqrt(2).
  EXPECT_NEAR(m.max_curvature, 1.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m.min_clearance, std::hypot(2.0, 2.0) - 1.0, 1e-12);
  EXPECT_TRUE(m.collision_free);
}

TEST(PathMetricsTest, StraightAndRepeatedPointsHaveNoTurns) {
  const Map map = OpenWorld();
  const PathMetrics m = EvaluatePath(map, {P(1, 1), P(2, 1), P(2, 1), P(4, 1), P(9, 1)}, 0.0);
  EXPECT_DOUBLE_EQ(m.length, 8.0);
  EXPECT_EQ(m.turning_points, 0);
  EXPECT_EQ(m.max_curvature, 0.0);
  EXPECT_TRUE(m.collision_free);
}

TEST(PathMetricsTest, ReversalHasInfiniteCurvature) {
  const Map map = OpenWorld();
  const PathMetrics m = EvaluatePath(map, {P(1, 1), P(3, 1), P(2, 1)}, 0.0);
  EXPECT_EQ(m.turning_points, 1);
  EXPECT_EQ(m.max_curvature, std::numeric_limits<double>::infinity());
}

TEST(PathMetricsTest, CurvatureOfARegularPolygonPath) {
  // Vertices on a circle of radius 3: the circumscribed-circle curvature is exactly 1/3.
  const Map map = OpenWorld();
  Path path;
  for (int k = 0; k <= 6; ++k) {
    const double a = k * std::numbers::pi / 8;
    path.push_back(P(5 + 3 * std::cos(a), 5 + 3 * std::sin(a)));
  }
  const PathMetrics m = EvaluatePath(map, path, 0.0);
  EXPECT_EQ(m.turning_points, 5);
  EXPECT_NEAR(m.max_curvature, 1.0 / 3.0, 1e-12);
}

TEST(PathMetricsTest, CollisionAndEmptyPath) {
  const Map map = OpenWorld();
  const PathMetrics through = EvaluatePath(map, {P(1, 5), P(9, 5)}, 0.0);
  EXPECT_FALSE(through.collision_free);
  EXPECT_LT(through.min_clearance, 0.0);
  const PathMetrics close = EvaluatePath(map, {P(1, 6.5), P(9, 6.5)}, 0.6);
  EXPECT_FALSE(close.collision_free);
  EXPECT_DOUBLE_EQ(close.min_clearance, 0.5);
  const PathMetrics empty = EvaluatePath(map, {}, 0.0);
  EXPECT_FALSE(empty.collision_free);
  EXPECT_EQ(empty.length, 0.0);
  const PathMetrics outside = EvaluatePath(map, {P(1, 1), P(11, 1)}, 0.0);
  EXPECT_FALSE(outside.collision_free);
}

TEST(PathMetricsTest, TerrainLengthInWorldUnits) {
  // Cells of 30 m, lower-left corner at the origin: cell centres at x, y = 15, 45, 75.
  const Map map(*Terrain::Create(3, 3, std::vector<double>(9, 0.0), 30.0, Point2::Zero(), 10.0));
  const PathMetrics m = EvaluatePath(map, {P(15, 15, 1), P(75, 15, 1), P(75, 75, 3)}, 0.5);
  EXPECT_NEAR(m.length, 60.0 + std::sqrt(3600.0 + 4.0), 1e-12);
  EXPECT_EQ(m.turning_points, 1);
  EXPECT_TRUE(m.collision_free);
  EXPECT_DOUBLE_EQ(m.min_clearance, 1.0);
}

TEST(PathMetricsTest, TerrainMinClearanceIsExactBetweenVertices) {
  // A ridge 4 high along the middle column: a path from 5 above the ground on one side to the
  // other passes 1 above the ridge top, half way between its vertices.
  const Map map(*Terrain::Create(3, 2, {0, 4, 0, 0, 4, 0}, 10.0, Point2::Zero(), 20.0));
  const PathMetrics m = EvaluatePath(map, {P(5, 5, 5), P(25, 5, 5)}, 0.0);
  EXPECT_DOUBLE_EQ(m.min_clearance, 1.0);
  EXPECT_TRUE(m.collision_free);
  EXPECT_FALSE(EvaluatePath(map, {P(5, 5, 3), P(25, 5, 3)}, 0.0).collision_free);
}

TEST(PathLengthTest, Polyline) {
  EXPECT_EQ(PathLength({}), 0.0);
  EXPECT_EQ(PathLength({P(1, 2)}), 0.0);
  EXPECT_DOUBLE_EQ(PathLength({P(0, 0), P(3, 4), P(3, 0)}), 9.0);
}

}  // namespace
}  // namespace swarmplan
