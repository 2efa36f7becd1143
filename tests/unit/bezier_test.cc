#include "core/smoothing/bezier.h"

#include <algorithm>
#include <cmath>

#include "core/graph/grid_search.h"
#include "core/smoothing/smoothing.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

// A world with one disc obstacle.
class DiscChecker final : public CollisionChecker {
 public:
  DiscChecker(Point2 centre, double radius) : centre_(centre), radius_(radius) {}
  double Clearance(const Point3& p) const override {
    return (Point2(p.x(), p.y()) - centre_).norm() - radius_;
  }
  double SegmentClearance(const Point3& a, const Point3& b) const override {
    const Point2 a2(a.x(), a.y()), b2(b.x(), b.y());
    const Point2 ab = b2 - a2;
    double t = ab.squaredNorm() > 0 ? (centre_ - a2).dot(ab) / ab.squaredNorm() : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return (a2 + t * ab - centre_).norm() - radius_;
  }

 private:
  Point2 centre_;
  double radius_;
};

TEST(BezierTest, ConstantsAreThePublishedOnes) {
  EXPECT_NEAR(BezierConstants::c2, 0.5798, 1e-4);
  EXPECT_NEAR(BezierConstants::c3, 0.3460, 1e-4);
  EXPECT_NEAR(BezierConstants::c4, 1.1226, 1e-4);
}

class BezierCornerTest : public ::testing::TestWithParam<double> {};

TEST_P(BezierCornerTest, CurvatureIsZeroAtTheEndsAndPeaksAtTheJoint) {
  const double heading_change = GetParam();
  const Point2 w(0, 0), prev(-10, 0);
  const Point2 next = 10.0 * Point2(std::cos(heading_change), std::sin(heading_change));
  const double d = 2.0;
  const BezierCorner c = MakeBezierCorner(prev, w, next, d);
  EXPECT_NEAR(c.beta, heading_change / 2, 1e-12);
  const double kmax = BezierCornerCurvature(c.beta, d);
  EXPECT_NEAR(std::abs(CubicBezierCurvature(c.b, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(CubicBezierCurvature(c.e, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(CubicBezierCurvature(c.b, 1.0)), kmax, 1e-3 * kmax);
  EXPECT_NEAR(std::abs(CubicBezierCurvature(c.e, 1.0)), kmax, 1e-3 * kmax);
  // Curvature never exceeds the joint's along either curve.
  for (int i = 0; i <= 200; ++i) {
    const double s = i / 200.0;
    EXPECT_LE(std::abs(CubicBezierCurvature(c.b, s)), kmax * (1 + 1e-3)) << s;
    EXPECT_LE(std::abs(CubicBezierCurvature(c.e, s)), kmax * (1 + 1e-3)) << s;
  }
  // The ends sit on the two lines at distance d from the corner.
  EXPECT_NEAR((c.b[0] - w).norm(), d, 1e-12);
  EXPECT_NEAR((c.e[0] - w).norm(), d, 1e-12);
}

TEST_P(BezierCornerTest, G2ContinuousAcrossTheJoint) {
  const double heading_change = GetParam();
  const Point2 next = 10.0 * Point2(std::cos(heading_change), std::sin(heading_change));
  const BezierCorner c = MakeBezierCorner(Point2(-10, 0), Point2(0, 0), next, 3.0);
  // In path order the second curve runs backwards: e[3] -> e[0].
  const Point2 reversed[4] = {c.e[3], c.e[2], c.e[1], c.e[0]};
  EXPECT_NEAR((CubicBezierPoint(c.b, 1.0) - CubicBezierPoint(reversed, 0.0)).norm(), 0.0, 1e-12);
  const Point2 t1 = (c.b[3] - c.b[2]).normalized();
  const Point2 t2 = (reversed[1] - reversed[0]).normalized();
  EXPECT_NEAR((t1 - t2).norm(), 0.0, 1e-9);
  EXPECT_NEAR(CubicBezierCurvature(c.b, 1.0), CubicBezierCurvature(reversed, 0.0), 1e-9);
  // Tangent continuity where the curves meet the straight lines.
  EXPECT_NEAR(std::abs((c.b[1] - c.b[0]).normalized().dot(Point2(1, 0))), 1.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(HeadingChanges, BezierCornerTest,
                         ::testing::Values(0.2, M_PI / 4, M_PI / 2, 2.0, 2.8));

TEST(BezierTest, DistanceComesFromTheTurningRadius) {
  const Path raw{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}};
  BezierOptions options;
  options.min_turning_radius = 2.0;
  const BezierResult r = SmoothWithBezier(raw, options, nullptr);
  EXPECT_EQ(r.corners, 1);
  EXPECT_EQ(r.corners_limited, 0);
  EXPECT_NEAR(r.max_curvature, 0.5, 1e-9);
  EXPECT_EQ(r.path.front(), raw.front());
  EXPECT_EQ(r.path.back(), raw.back());
  // d = c4 sin β / (κ cos² β) with β = 45°.
  EXPECT_NEAR(BezierDistanceForCurvature(M_PI / 4, 0.5), 2.0 * 1.1226 * std::sqrt(2.0), 1e-3);
}

TEST(BezierTest, NeighbouringCornersNeverOverlap) {
  // A zigzag with short legs: the corners want more room than the segments have.
  const Path raw{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}, {6, 2, 0}};
  BezierOptions options;
  options.min_turning_radius = 5.0;
  const BezierResult r = SmoothWithBezier(raw, options, nullptr);
  EXPECT_EQ(r.corners, 4);
  EXPECT_GT(r.corners_limited, 0);
  EXPECT_GT(r.max_curvature, 1.0 / 5.0);  // the curvature reached is reported
  // The smoothed path visits the corners' curves in order: x never goes back.
  for (size_t i = 1; i < r.path.size(); ++i) {
    EXPECT_GE(r.path[i].x(), r.path[i - 1].x() - 1e-9) << i;
  }
  // Each curve stays within the corner's triangle, so the path is no longer than the raw one.
  double raw_len = 0, smooth_len = 0;
  for (size_t i = 1; i < raw.size(); ++i) raw_len += (raw[i] - raw[i - 1]).norm();
  for (size_t i = 1; i < r.path.size(); ++i) smooth_len += (r.path[i] - r.path[i - 1]).norm();
  EXPECT_LT(smooth_len, raw_len);
}

TEST(BezierTest, CollinearPointsArePrunedFirst) {
  const Path raw{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  const BezierResult r = SmoothWithBezier(raw, BezierOptions{}, nullptr);
  EXPECT_EQ(r.corners, 0);
  ASSERT_EQ(r.path.size(), 2u);
}

TEST(BezierTest, ShrinksACornerThatWouldHitAnObstacle) {
  const Path raw{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}};
  // A disc inside the bend, close to the corner: the wide curve would cut through it.
  const DiscChecker checker(Point2(8.6, 1.4), 0.5);
  ASSERT_TRUE(checker.PathFree(raw, 0.0));
  BezierOptions options;
  options.min_turning_radius = 3.0;
  const BezierResult unchecked = SmoothWithBezier(raw, options, nullptr);
  EXPECT_FALSE(checker.PathFree(unchecked.path, 0.0));
  const BezierResult r = SmoothWithBezier(raw, options, &checker);
  EXPECT_TRUE(r.collision_free);
  EXPECT_EQ(r.corners_shrunk, 1);
  EXPECT_EQ(r.corners_sharp, 0);
  EXPECT_GT(r.max_curvature, 1.0 / 3.0);
}

TEST(BezierTest, LeavesTheCornerSharpWhenNothingFits) {
  const Path raw{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}};
  // Inside the bend, exactly `clearance` from both legs: any wide curve comes too close.
  const DiscChecker checker(Point2(9, 1), 0.5);
  BezierOptions options;
  options.clearance = 0.5;
  options.min_turning_radius = 3.0;
  options.max_shrinks = 0;
  ASSERT_TRUE(checker.PathFree(raw, options.clearance));
  const BezierResult r = SmoothWithBezier(raw, options, &checker);
  EXPECT_EQ(r.corners_sharp, 1);
  EXPECT_TRUE(r.collision_free);
  EXPECT_EQ(r.path.size(), 3u);
}

TEST(BezierTest, IsASmoothingMethodForGridPaths) {
  const std::vector<std::string> methods = SmoothingMethods();
  EXPECT_NE(std::find(methods.begin(), methods.end(), "bezier"), methods.end());
  const MapPtr map = testing::GridMap(testing::TwoWallsRows());
  const OccupancyGrid& grid = *map->grid();
  const std::optional<std::vector<Cell>> cells = AStarCells(grid, Cell{0, 0}, Cell{11, 11});
  ASSERT_TRUE(cells.has_value());
  const Path raw = CellPathToWorld(grid, *cells);
  absl::StatusOr<SmoothingResult> smoothed = Smooth("bezier", *map, raw, 0.0);
  ASSERT_TRUE(smoothed.ok()) << smoothed.status();
  EXPECT_TRUE(smoothed->collision_free);
  EXPECT_EQ(smoothed->path.front(), raw.front());
  EXPECT_EQ(smoothed->path.back(), raw.back());
  EXPECT_GT(smoothed->path.size(), raw.size());
}

}  // namespace
}  // namespace swarmplan
