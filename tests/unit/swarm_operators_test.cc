#include <cmath>
#include <numbers>

#include "core/operators/antennae.h"
#include "core/operators/elite_mutation.h"
#include "core/operators/good_point_set.h"
#include "core/operators/inertia.h"
#include "core/operators/obstacle_proximity.h"
#include "core/operators/waypoint_objective.h"
#include "core/operators/waypoint_path.h"
#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

TEST(GoodPointSetTest, MatchesHandComputedPoints) {
  EXPECT_EQ(SmallestPrimeAtLeast(5), 5);
  EXPECT_EQ(SmallestPrimeAtLeast(7), 7);
  EXPECT_EQ(SmallestPrimeAtLeast(63), 67);
  // D = 1: p = 5, r = 2 cos(2 pi / 5) = 0.618034.
  const auto one = GoodPointSet(3, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1));
  ASSERT_EQ(one.size(), 3u);
  EXPECT_NEAR(one[0][0], 0.6180340, 1e-6);
  EXPECT_NEAR(one[1][0], 0.2360680, 1e-6);
  EXPECT_NEAR(one[2][0], 0.8541020, 1e-6);
  // D = 2: p = 7, r = (2 cos(2 pi / 7), 2 cos(4 pi / 7)) = (1.2469796, -0.4450419); the
  // fractional part of a negative number is taken non-negative.
  const auto two = GoodPointSet(2, Eigen::Vector2d(0, -10), Eigen::Vector2d(10, 10));
  EXPECT_NEAR(two[0][0], 2.469796, 1e-5);
  EXPECT_NEAR(two[0][1], -10 + 20 * 0.5549581, 1e-5);
  EXPECT_NEAR(two[1][0], 10 * (2.4939592 - 2), 1e-5);
  EXPECT_NEAR(two[1][1], -10 + 20 * (-0.8900838 + 1), 1e-5);
}

TEST(InertiaTest, SchedulesAtStartMiddleAndEnd) {
  EXPECT_DOUBLE_EQ(InertiaWeight(InertiaSchedule::kLinear, 0.9, 0.4, 0, 500), 0.9);
  EXPECT_NEAR(InertiaWeight(InertiaSchedule::kLinear, 0.9, 0.4, 250, 500), 0.65, 1e-12);
  EXPECT_NEAR(InertiaWeight(InertiaSchedule::kLinear, 0.9, 0.4, 500, 500), 0.4, 1e-12);
  EXPECT_DOUBLE_EQ(InertiaWeight(InertiaSchedule::kCosine, 0.9, 0.4, 0, 500), 0.9);
  EXPECT_NEAR(InertiaWeight(InertiaSchedule::kCosine, 0.9, 0.4, 250, 500),
              0.4 + 0.5 * std::cos(std::numbers::pi / 2 * std::sqrt(0.5)), 1e-12);
  EXPECT_NEAR(InertiaWeight(InertiaSchedule::kCosine, 0.9, 0.4, 250, 500), 0.622008, 1e-6);
  EXPECT_NEAR(InertiaWeight(InertiaSchedule::kCosine, 0.9, 0.4, 500, 500), 0.4, 1e-12);
  EXPECT_TRUE(ParseInertiaSchedule("cosine").ok());
  EXPECT_FALSE(ParseInertiaSchedule("sine").ok());
}

TEST(EliteMutationTest, ScalesTheWholeVectorByOneFactor) {
  const EliteMutation mutation{0.1, 0.1, -1.0};
  Rng rng(7);
  const Eigen::Vector3d gbest(1.0, -2.0, 4.0);
  for (int i = 0; i < 200; ++i) {
    Eigen::VectorXd out;
    mutation.Mutate(gbest, 50, 100, 10.0, 10.0, rng, out);
    const double factor = out[0] / gbest[0];
    EXPECT_NEAR(out[1], gbest[1] * factor, 1e-12);
    EXPECT_NEAR(out[2], gbest[2] * factor, 1e-12);
    // G1 = 0.05, G2 = 0.1 exp(0) = 0.1: s in [0.15, 1.15).
    const bool plus = factor >= 1.15 - 1e-12 && factor < 2.15;
    const bool minus = factor > 1 - 1.15 && factor <= 1 - 0.15 + 1e-12;
    EXPECT_TRUE(plus || minus) << factor;
  }
  // A huge gap with k3 > 0 stays finite.
  const EliteMutation steep{0.1, 0.1, 1.0};
  EXPECT_TRUE(std::isfinite(steep.Factor(0, 10, 1e9, 0.0, rng)));
}

// f(x) = |x|^2 on [-10, 10]^2.
class Sphere final : public Objective {
 public:
  int dim() const override { return 2; }
  const Eigen::VectorXd& lower() const override { return lo_; }
  const Eigen::VectorXd& upper() const override { return hi_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override { return {x.squaredNorm(), true}; }

 private:
  Eigen::VectorXd lo_ = Eigen::Vector2d(-10, -10), hi_ = Eigen::Vector2d(10, 10);
};

TEST(AntennaeTest, StepsTowardTheBetterAntenna) {
  Sphere sphere;
  Eigen::VectorXd scratch;
  const Eigen::VectorXd x = Eigen::Vector2d(3, 0);
  const Eigen::VectorXd b = Eigen::Vector2d(1, 0);
  const AntennaeProbe probe = ProbeAntennae(sphere, x, b, 1.0, scratch);
  EXPECT_DOUBLE_EQ(probe.f_right, 16.0);
  EXPECT_DOUBLE_EQ(probe.f_left, 4.0);
  EXPECT_EQ(probe.toward_right, -1.0);
  Eigen::VectorXd moved = x;
  AddAntennaeStep(probe, b, 2.0, moved);
  EXPECT_EQ(moved, Eigen::VectorXd(Eigen::Vector2d(1, 0)));
}

ShapeWorld OneCircleWorld() { return *ShapeWorld::Create({{0, 0}, {10, 10}}, {{{5, 5}, 1.0}}, {}); }

TEST(ObstacleProximityTest, CountsObstaclesCloserThanTheThresholdOnShapes) {
  const Map map(*ShapeWorld::Create({{0, 0}, {10, 10}}, {{{5, 5}, 1.0}},
                                    {Polygon{{{7, 1}, {9, 1}, {9, 2}, {7, 2}}}}));
  absl::StatusOr<ObstacleProximity> proximity = ObstacleProximity::Create(map, 1.5);
  ASSERT_TRUE(proximity.ok());
  EXPECT_EQ(proximity->CountViolations({{0, 5, 0}, {10, 5, 0}}), 1);      // through the circle
  EXPECT_EQ(proximity->CountViolations({{0, 7.4, 0}, {10, 7.4, 0}}), 1);  // 1.4 from it
  EXPECT_EQ(proximity->CountViolations({{0, 7.6, 0}, {10, 7.6, 0}}), 0);  // 1.6 from it
  EXPECT_EQ(proximity->CountViolations({{0, 3, 0}, {10, 3, 0}}), 2);      // 1 from both
  EXPECT_EQ(proximity->CountViolations({{0, 9, 0}, {11, 9, 0}}), 1);      // leaves the map
}

TEST(ObstacleProximityTest, CountsDistinctComponentsOnGrids) {
  // Two blocks of blocked cells on a 12 x 5 grid, in columns 3-4 and 8.
  std::vector<int8_t> cells(12 * 5, 0);
  for (int y = 0; y < 3; ++y) {
    cells[y * 12 + 3] = cells[y * 12 + 4] = 100;
    cells[y * 12 + 8] = 100;
  }
  const Map map(*OccupancyGrid::Create(12, 5, cells));
  absl::StatusOr<ObstacleProximity> proximity = ObstacleProximity::Create(map, 1.5);
  ASSERT_TRUE(proximity.ok());
  EXPECT_EQ(proximity->obstacle_count(), 2);
  EXPECT_EQ(proximity->CountViolations({{0.5, 1.5, 0}, {11.5, 1.5, 0}}), 2);
  EXPECT_EQ(proximity->CountViolations({{0.5, 4.5, 0}, {11.5, 4.5, 0}}), 0);
  EXPECT_EQ(proximity->CountViolations({{0.5, 3.5, 0}, {11.5, 3.5, 0}}), 2);  // one cell above
  EXPECT_EQ(proximity->CountViolations({{0.5, 0.5, 0}, {2.5, 0.5, 0}}), 1);
}

TEST(WaypointPathTest, BuildsSplineLinearAndStaircasePaths) {
  const Eigen::VectorXd x = Eigen::Vector2d(5, 5);  // one waypoint at (5, 5)
  WaypointPathBuilder linear({0, 0, 0}, {10, 0, 0}, 1, Interpolation::kLinear, 100);
  EXPECT_EQ(linear.Build(x), Path({{0, 0, 0}, {5, 5, 0}, {10, 0, 0}}));
  WaypointPathBuilder nearest({0, 0, 0}, {10, 0, 0}, 1, Interpolation::kNearest, 100);
  EXPECT_EQ(
      nearest.Build(x),
      Path({{0, 0, 0}, {2.5, 0, 0}, {2.5, 5, 0}, {5, 5, 0}, {7.5, 5, 0}, {7.5, 0, 0}, {10, 0, 0}}));
  WaypointPathBuilder spline({0, 0, 0}, {10, 0, 0}, 1, Interpolation::kSpline, 101);
  const Path& path = spline.Build(x);
  ASSERT_EQ(path.size(), 101u);
  EXPECT_EQ(path.front(), Point3(0, 0, 0));
  EXPECT_EQ(path.back(), Point3(10, 0, 0));
  EXPECT_NEAR((path[50] - Point3(5, 5, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(path[25].y(), 3.75, 1e-12);  // the parabola y = 5 (1 - (s - 1)^2) at s = 0.5
}

TEST(WaypointObjectiveTest, FitnessIsLengthTimesPenalty) {
  Problem problem;
  problem.map = std::make_shared<Map>(OneCircleWorld());
  problem.start = {1, 1, 0};
  problem.goal = {9, 1, 0};
  WaypointFitnessOptions options;
  options.waypoints = 1;
  options.interpolation = Interpolation::kLinear;
  auto objective = WaypointObjective::Create(problem, options);
  ASSERT_TRUE(objective.ok());
  EXPECT_EQ((*objective)->dim(), 2);
  const Evaluation clear = (*objective)->Evaluate(Eigen::Vector2d(5, 1));
  EXPECT_TRUE(clear.feasible);
  EXPECT_NEAR(clear.fitness, 8.0, 1e-12);
  const Evaluation blocked = (*objective)->Evaluate(Eigen::Vector2d(5, 5));
  EXPECT_FALSE(blocked.feasible);
  EXPECT_NEAR(blocked.fitness, 2 * std::hypot(4, 4) * 101, 1e-9);
}

}  // namespace
}  // namespace swarmplan
