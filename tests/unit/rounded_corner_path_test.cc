#include "core/fitness/rounded_corner_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/fitness/fitness_engine.h"
#include "core/geometry/collision.h"
#include "core/path_metrics.h"
#include "core/random.h"
#include "core/smoothing/bounded_curvature.h"
#include "tests/unit/contract_checks.h"
#include "tests/unit/seed_test_maps.h"

namespace swarmplan {
namespace {

// The points RoundedCornerPath makes of the polygon's vertices, as a path.
Path Round(const Path& polygon, double radius, double spacing, int max_points) {
  const RoundedCornerPath rounding(static_cast<int>(polygon.size()), radius, spacing, max_points);
  std::vector<double> kx, ky;
  for (const Point3& p : polygon) {
    kx.push_back(p.x());
    ky.push_back(p.y());
  }
  std::vector<double> px(rounding.max_points()), py(rounding.max_points());
  std::vector<double> scratch(2 * polygon.size());
  const int n = rounding.Apply(kx.data(), ky.data(), px.data(), py.data(), scratch.data());
  EXPECT_LE(n, rounding.max_points());
  Path path;
  for (int i = 0; i < n; ++i) path.emplace_back(px[i], py[i], 0.0);
  return path;
}

// The largest distance from a point of `a` to the polyline `b`.
double FarthestFrom(const Path& a, const Path& b) {
  double farthest = 0.0;
  for (const Point3& p : a) {
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i + 1 < b.size(); ++i) {
      nearest = std::min(
          nearest, contract::PointSegmentDistance(p.head<2>(), b[i].head<2>(), b[i + 1].head<2>()));
    }
    farthest = std::max(farthest, nearest);
  }
  return farthest;
}

TEST(RoundedCornerPathTest, RoundsTheSmoothingsCornersAsTheSmoothingDoes) {
  const MapPtr map = seed_testing::BlockWorld();
  const auto checker = MakeCollisionChecker(*map);
  const Path raw{{5, 15, 0}, {9.5, 11.5, 0}, {30.5, 11.5, 0}, {35, 15, 0}};
  BoundedCurvatureOptions options;
  options.turning_radius = 2.0;
  options.clearance = 0.5;
  const BoundedCurvatureResult smoothed = SmoothToTurningRadius(raw, options, *checker);
  ASSERT_TRUE(smoothed.collision_free);
  ASSERT_EQ(smoothed.corners_over, 0);
  ASSERT_GE(smoothed.corner_polygon.size(), 3u);

  const Path rounded = Round(smoothed.corner_polygon, 2.0, 0.25, 400);
  EXPECT_EQ(rounded.front(), raw.front());
  EXPECT_EQ(rounded.back(), raw.back());
  // The same curves, sampled at other points: apart by no more than a chord's sagitta.
  EXPECT_LT(FarthestFrom(rounded, smoothed.path), 0.02);
  EXPECT_LT(FarthestFrom(smoothed.path, rounded), 0.02);
  EXPECT_TRUE(checker->PathFree(rounded, 0.5));
  EXPECT_LE(contract::LargestMengerCurvature(rounded), 0.5);
  // It samples a curve within the radius, so the smoothing keeps it as it is.
  EXPECT_EQ(SmoothToTurningRadius(rounded, options, *checker).path, rounded);
}

TEST(RoundedCornerPathTest, ACornerWithoutRoomTurnsTighter) {
  // Two corners 0.3 apart turning 90 degrees each: a radius of 2 needs several units of line.
  const Path polygon{{0, 0, 0}, {10, 0, 0}, {10, 0.3, 0}, {0, 0.3, 0}};
  const Path rounded = Round(polygon, 2.0, 0.5, 100);
  EXPECT_EQ(rounded.front(), polygon.front());
  EXPECT_EQ(rounded.back(), polygon.back());
  EXPECT_GT(contract::LargestMengerCurvature(rounded), 0.5);
}

TEST(RoundedCornerPathTest, CollinearKnotsGiveTheStraightLine) {
  const Path polygon{{0, 1, 0}, {4, 1, 0}, {10, 1, 0}};
  const Path rounded = Round(polygon, 2.0, 0.5, 100);
  EXPECT_EQ(rounded.front(), polygon.front());
  EXPECT_EQ(rounded.back(), polygon.back());
  for (size_t i = 0; i < rounded.size(); ++i) {
    EXPECT_EQ(rounded[i].y(), 1.0);
    if (i > 0) {
      EXPECT_GT(rounded[i].x(), rounded[i - 1].x());
      EXPECT_LE(rounded[i].x() - rounded[i - 1].x(), 0.5 + 1e-12);
    }
  }
  EXPECT_EQ(MeasureTurns(rounded).turning_points, 0);
}

TEST(RoundedCornerPathTest, StaysWithinItsPointsOnAnyKnots) {
  Rng rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    Path polygon;
    const int knots = static_cast<int>(rng.UniformInt(2, 12));
    for (int i = 0; i < knots; ++i) {
      polygon.emplace_back(rng.Uniform(0, 1000), rng.Uniform(0, 1000), 0.0);
    }
    // Repeated and reversed knots as a swarm makes them.
    if (knots > 3) {
      polygon[2] = polygon[1];
      polygon[3] = polygon[1] + 0.5 * (polygon[0] - polygon[1]);
    }
    if (knots > 5) polygon[5] = polygon[4] + 0.5 * (polygon[3] - polygon[4]);
    // Radii a request may give, extremes included.
    const double radius = trial % 10 == 0 ? 1e-300 : trial % 10 == 1 ? 1e300 : rng.Uniform(0.1, 50);
    const Path rounded = Round(polygon, radius, 0.5, 64);
    ASSERT_GE(rounded.size(), 2u);
    EXPECT_EQ(rounded.front(), polygon.front());
    EXPECT_EQ(rounded.back(), polygon.back());
    for (const Point3& p : rounded) EXPECT_TRUE(p.allFinite());
  }
}

// The engine decodes its waypoints into RoundedCornerPath's path and evaluates that path.
TEST(RoundedCornerPathTest, TheFitnessEngineEvaluatesTheRoundedPath) {
  Problem problem;
  problem.map = seed_testing::BlockWorld();
  problem.start = {5, 15, 0};
  problem.goal = {35, 15, 0};
  problem.clearance = 0.5;
  WaypointFitnessOptions options;
  options.waypoints = 2;
  options.samples = 200;
  options.fleet = FleetObjective{.preferred_clearance = 1.5, .turning_radius = 2.0};
  options.rounded_corner_radius = 2.0;
  absl::StatusOr<FitnessEngine> engine = FitnessEngine::Create(problem, options);
  ASSERT_TRUE(engine.ok()) << engine.status();
  const Eigen::VectorXd x = (Eigen::VectorXd(4) << 9.5, 30.5, 11.0, 11.0).finished();
  Path decoded;
  engine->Decode(x, decoded);
  const Path polygon{problem.start, {9.5, 11, 0}, {30.5, 11, 0}, problem.goal};
  EXPECT_EQ(decoded,
            Round(polygon, 2.0, 0.5 * problem.map->world()->distance_field().cell_size(), 200));
  EXPECT_NEAR(engine->Terms(x).length, PathLength(decoded), 1e-9);
  EXPECT_EQ(engine->Evaluate(x).feasible,
            MakeCollisionChecker(*problem.map)->PathFree(decoded, 0.5));

  options.rounded_corner_radius = -1.0;
  EXPECT_FALSE(FitnessEngine::Create(problem, options).ok());
}

}  // namespace
}  // namespace swarmplan
