// The timing of a path for a vehicle (core/timing): the fastest profile within the top speed,
// the acceleration along and across the path and the yaw rate, at rest at both ends; and a plan
// that asks for it.

#include "core/timing/timed_path.h"

#include <cmath>
#include <numbers>

#include "core/path_metrics.h"
#include "core/run.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"
#include "tests/unit/plan_test_support.h"

namespace swarmplan {
namespace {

VehicleLimits Vehicle(double speed, double acceleration, double yaw_rate = 0.0) {
  VehicleLimits vehicle;
  vehicle.max_speed = speed;
  vehicle.max_acceleration = acceleration;
  vehicle.max_yaw_rate = yaw_rate;
  return vehicle;
}

// Every limit, checked point by point: the curvature's bounds at each vertex, the acceleration
// between neighbours, time rising, at rest at both ends.
void ExpectWithinLimits(const Path& path, const TimedPath& timed, const VehicleLimits& vehicle) {
  ASSERT_EQ(timed.points.size(), path.size());
  const double slack = 1.0 + 1e-9;
  EXPECT_EQ(timed.points.front().speed, 0.0);
  EXPECT_EQ(timed.points.back().speed, 0.0);
  EXPECT_EQ(timed.points.front().time, 0.0);
  EXPECT_EQ(timed.points.back().time, timed.duration);
  for (size_t i = 0; i < path.size(); ++i) {
    const TimedPoint& p = timed.points[i];
    EXPECT_EQ(p.point, path[i]);
    EXPECT_LE(p.speed, vehicle.max_speed * slack);
    if (i > 0 && i + 1 < path.size() && p.speed > 0) {
      const double kappa = DiscreteCurvature(path[i - 1], path[i], path[i + 1]);
      EXPECT_LE(p.speed * p.speed * kappa, vehicle.max_acceleration * slack) << "point " << i;
      if (vehicle.max_yaw_rate > 0) {
        EXPECT_LE(p.speed * kappa, vehicle.max_yaw_rate * slack) << "point " << i;
      }
    }
    if (i > 0) {
      const TimedPoint& q = timed.points[i - 1];
      const double s = (path[i] - path[i - 1]).norm();
      EXPECT_LE(std::abs(p.speed * p.speed - q.speed * q.speed),
                2.0 * vehicle.max_acceleration * s * slack + 1e-12);
      EXPECT_GE(p.time, q.time);
      // No faster than the top speed over the segment.
      EXPECT_GE(p.time - q.time, s / vehicle.max_speed / slack);
    }
  }
}

TEST(TimedPathTest, AStraightLineIsATrapezoid) {
  const Path line{{0, 0, 0}, {10, 0, 0}};
  const VehicleLimits vehicle = Vehicle(2.0, 1.0);
  const TimedPath timed = TimePath(line, vehicle);
  ExpectWithinLimits(line, timed, vehicle);
  // 2 s up to 2 units/s over 2 units, 6 units at 2 units/s, 2 s down.
  EXPECT_NEAR(timed.duration, 7.0, 1e-12);
  // Too short to reach the top speed: a triangle, sqrt(s / a) up and as long down.
  const TimedPath short_line = TimePath({{0, 0, 0}, {1, 0, 0}}, vehicle);
  EXPECT_NEAR(short_line.duration, 2.0, 1e-12);
  // Intermediate points on the line change nothing.
  const Path sampled{{0, 0, 0}, {1, 0, 0}, {2.5, 0, 0}, {7, 0, 0}, {10, 0, 0}};
  const TimedPath same = TimePath(sampled, vehicle);
  ExpectWithinLimits(sampled, same, vehicle);
  EXPECT_NEAR(same.duration, 7.0, 1e-12);
  EXPECT_NEAR(same.points[2].speed, 2.0, 1e-12);
}

TEST(TimedPathTest, CurvesSlowTheVehicleByAccelerationAndYawRate) {
  // A half circle of radius 2 sampled every 1 degree, between two straight runs of 10.
  Path path{{-10, 0, 0}};
  for (int degrees = 0; degrees <= 180; ++degrees) {
    const double t = degrees * std::numbers::pi / 180.0;
    path.push_back({2.0 * std::sin(t), 2.0 - 2.0 * std::cos(t), 0});
  }
  path.push_back({-10, 4, 0});
  const VehicleLimits loose = Vehicle(3.0, 1.0);
  const TimedPath by_acceleration = TimePath(path, loose);
  ExpectWithinLimits(path, by_acceleration, loose);
  // On the arc the speed is sqrt(a R) = sqrt(2) (the discrete curvature of the samples is that
  // of the circle).
  EXPECT_NEAR(by_acceleration.points[92].speed, std::sqrt(2.0), 1e-6);

  const VehicleLimits turning = Vehicle(3.0, 1.0, 0.5);
  const TimedPath by_yaw = TimePath(path, turning);
  ExpectWithinLimits(path, by_yaw, turning);
  EXPECT_NEAR(by_yaw.points[92].speed, 1.0, 1e-6);  // omega R
  EXPECT_GT(by_yaw.duration, by_acceleration.duration);
  // The arc alone takes at least pi R / (omega R).
  EXPECT_GE(by_yaw.points[182].time - by_yaw.points[1].time, std::numbers::pi / 0.5 - 1e-9);
}

TEST(TimedPathTest, AReversalIsPassedAtRest) {
  const Path there_and_back{{0, 0, 0}, {4, 0, 0}, {1, 0, 0}};
  const VehicleLimits vehicle = Vehicle(5.0, 2.0);
  const TimedPath timed = TimePath(there_and_back, vehicle);
  ExpectWithinLimits(there_and_back, timed, vehicle);
  EXPECT_EQ(timed.points[1].speed, 0.0);
  EXPECT_NEAR(timed.duration, 2.0 * std::sqrt(4.0 / 2.0) + 2.0 * std::sqrt(3.0 / 2.0), 1e-12);
}

TEST(TimedPathTest, InvalidLimitsNameTheirField) {
  EXPECT_TRUE(ValidateVehicleLimits(Vehicle(0, 0)).ok()) << "not timed";
  EXPECT_TRUE(ValidateVehicleLimits(Vehicle(1, 0.5, 0.2)).ok());
  absl::Status negative = ValidateVehicleLimits(Vehicle(-1, 1));
  EXPECT_EQ(negative.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(negative.message().find("vehicle.max_speed"), std::string::npos) << negative;
  absl::Status no_acceleration = ValidateVehicleLimits(Vehicle(1, 0));
  EXPECT_NE(no_acceleration.message().find("vehicle.max_acceleration"), std::string::npos)
      << no_acceleration;
  absl::Status yaw = ValidateVehicleLimits(Vehicle(1, 1, std::nan("")));
  EXPECT_NE(yaw.message().find("vehicle.max_yaw_rate"), std::string::npos) << yaw;
}

TEST(TimedPathTest, APlanWithAVehicleCarriesItsFinalPathTimed) {
  PlanRequest request;
  request.algorithm = "theta-star";
  request.problem =
      testing::GridProblemFor(testing::GridMap(testing::TwoWallsRows()), {0, 11}, {11, 0});
  request.smoothing = "bounded-curvature";
  testing::NullObserver observer;
  absl::StatusOr<PlanResult> untimed = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_TRUE(untimed.ok()) << untimed.status();
  EXPECT_FALSE(untimed->timed_path.has_value());

  request.vehicle = Vehicle(1.5, 0.5, 1.0);
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->found && result->smoothing_collision_free);
  ASSERT_TRUE(result->timed_path.has_value());
  ExpectWithinLimits(result->smoothed_path, *result->timed_path, request.vehicle);
  EXPECT_GT(result->timed_path->duration, PathLength(result->smoothed_path) / 1.5);

  request.vehicle = Vehicle(1.5, 0.0);
  absl::StatusOr<PlanResult> rejected = RunPlan(DefaultRegistry(), request, StopToken(), observer);
  EXPECT_EQ(rejected.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(rejected.status().message().find("vehicle.max_acceleration"), std::string::npos);
}

}  // namespace
}  // namespace swarmplan
