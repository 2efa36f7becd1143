#include <cmath>

#include "core/map/map.h"
#include "core/smoothing/cubic_spline.h"
#include "core/smoothing/smoothing.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

std::vector<Point3> CubicKnots(int n) {
  std::vector<Point3> knots;
  for (int s = 0; s < n; ++s) knots.emplace_back(s, s * s * s, 0.0);
  return knots;
}

TEST(CubicSplineTest, PassesThroughItsKnots) {
  const std::vector<Point3> knots = {{0, 0, 0}, {2, 3, 1}, {5, 1, 0}, {6, 6, 2}, {9, 4, 0}};
  for (SplineEnd end : {SplineEnd::kNotAKnot, SplineEnd::kNatural}) {
    CubicSpline spline;
    spline.Fit(knots, end);
    for (size_t i = 0; i < knots.size(); ++i) {
      EXPECT_NEAR((spline.Evaluate(static_cast<double>(i)) - knots[i]).norm(), 0.0, 1e-12);
    }
  }
}

TEST(CubicSplineTest, NotAKnotThroughThreePointsIsTheParabola) {
  CubicSpline spline;
  spline.Fit({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, SplineEnd::kNotAKnot);
  // x = s, y = 1 - (s - 1)^2.
  EXPECT_NEAR(spline.Evaluate(0.5).x(), 0.5, 1e-12);
  EXPECT_NEAR(spline.Evaluate(0.5).y(), 0.75, 1e-12);
  EXPECT_NEAR(spline.Evaluate(1.7).y(), 1.0 - 0.49, 1e-12);
}

TEST(CubicSplineTest, NaturalThroughThreePointsMatchesHandComputation) {
  CubicSpline spline;
  spline.Fit({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, SplineEnd::kNatural);
  // 4 M1 = 6 (0 - 2 + 0) gives M1 = -3; at s = 0.5: 0.5 + (0.125 - 0.5) (-3) / 6 = 0.6875.
  EXPECT_NEAR(spline.Evaluate(0.5).y(), 0.6875, 1e-12);
  EXPECT_NEAR(spline.Evaluate(1.5).y(), 0.6875, 1e-12);
  EXPECT_NEAR(spline.Evaluate(0.5).x(), 0.5, 1e-12);
}

TEST(CubicSplineTest, NotAKnotReproducesACubic) {
  for (int n : {4, 6}) {
    CubicSpline spline;
    spline.Fit(CubicKnots(n), SplineEnd::kNotAKnot);
    for (double s : {0.25, 1.5, 2.75, n - 1.1}) {
      EXPECT_NEAR(spline.Evaluate(s).y(), s * s * s, 1e-9) << "n=" << n << " s=" << s;
      EXPECT_NEAR(spline.Evaluate(s).x(), s, 1e-12);
    }
  }
}

TEST(CubicSplineTest, TwoKnotsGiveTheSegment) {
  const std::vector<Point3> samples = SplineThrough({{0, 0, 0}, {4, 2, 0}}, 5);
  ASSERT_EQ(samples.size(), 5u);
  EXPECT_NEAR((samples[2] - Point3(2, 1, 0)).norm(), 0.0, 1e-12);
}

TEST(CubicSplineTest, SamplesByCountIncludeTheEnds) {
  const std::vector<Point3> knots = {{0, 0, 0}, {3, 4, 0}, {7, 1, 0}, {10, 10, 0}};
  CubicSpline spline;
  spline.Fit(knots, SplineEnd::kNotAKnot);
  std::vector<Point3> out;
  spline.SampleByCount(100, out);
  ASSERT_EQ(out.size(), 100u);
  EXPECT_EQ(out.front(), knots.front());
  EXPECT_EQ(out.back(), knots.back());
  // Knot 1 sits at parameter 1 = sample 33 of 99 steps.
  EXPECT_NEAR((out[33] - knots[1]).norm(), 0.0, 1e-12);
}

TEST(CubicSplineTest, SamplesBySpacingKeepTheSpacingAndTheKnots) {
  const std::vector<Point3> knots = {{0, 0, 0}, {3, 4, 0}, {7, 1, 0}, {10, 10, 0}};
  CubicSpline spline;
  spline.Fit(knots, SplineEnd::kNotAKnot);
  std::vector<Point3> out;
  spline.SampleBySpacing(0.5, out);
  EXPECT_GT(out.size(), 40u);
  for (size_t i = 0; i + 1 < out.size(); ++i) EXPECT_LE((out[i + 1] - out[i]).norm(), 0.6);
  for (const Point3& k : knots) {
    EXPECT_NE(std::find(out.begin(), out.end(), k), out.end());
  }
}

TEST(CubicSplineTest, IsRegisteredAsSmoothingMethod) {
  const std::vector<std::string> methods = SmoothingMethods();
  EXPECT_NE(std::find(methods.begin(), methods.end(), "cubic-spline"), methods.end());
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create({{0, 0}, {10, 10}}, {}, {});
  ASSERT_TRUE(world.ok());
  const Map map(*world);
  absl::StatusOr<SmoothingResult> smoothed =
      Smooth("cubic-spline", map, {{1, 1, 0}, {5, 6, 0}, {9, 2, 0}}, 0.0);
  ASSERT_TRUE(smoothed.ok()) << smoothed.status();
  EXPECT_TRUE(smoothed->collision_free);
  EXPECT_EQ(smoothed->path.front(), Point3(1, 1, 0));
  EXPECT_EQ(smoothed->path.back(), Point3(9, 2, 0));
  EXPECT_GT(smoothed->path.size(), 10u);
}

}  // namespace
}  // namespace swarmplan
