#include "core/smoothing/bounded_curvature.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "core/geometry/collision.h"
#include "core/map/io/map_io.h"
#include "core/map/map.h"
#include "core/path_metrics.h"
#include "core/seeds/seed_paths.h"
#include "core/smoothing/bezier.h"
#include "core/smoothing/cubic_spline.h"
#include "core/smoothing/smoothing.h"
#include "tests/unit/seed_test_maps.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

MapPtr EmptyWorld() {
  return std::make_shared<const Map>(Map::Data(*ShapeWorld::Create({{0, 0}, {40, 30}}, {}, {})));
}

void ExpectSmoothedPath(const Map& map, const Path& raw, const BoundedCurvatureResult& r,
                        double radius, double clearance) {
  ASSERT_GE(r.path.size(), 2u);
  EXPECT_EQ(r.path.front(), raw.front());
  EXPECT_EQ(r.path.back(), raw.back());
  EXPECT_TRUE(r.collision_free);
  EXPECT_GE(seed_testing::Clearance(map, r.path), clearance - 1e-9);
  EXPECT_LE(contract::LargestMengerCurvature(r.path), 1.0 / radius);
  EXPECT_EQ(r.corners_over, 0);
}

TEST(BoundedCurvatureTest, RoundsTheCornersAroundABlockOutsideTheClearance) {
  const MapPtr map = seed_testing::BlockWorld();
  const auto checker = MakeCollisionChecker(*map);
  // Around the block's lower side at exactly the clearance: a curve inside either bend would
  // come too close, so the corners have to move out.
  const Path raw{{5, 15, 0}, {9.5, 11.5, 0}, {30.5, 11.5, 0}, {35, 15, 0}};
  ASSERT_TRUE(checker->PathFree(raw, 0.5));
  BoundedCurvatureOptions options;
  options.turning_radius = 2.0;
  options.clearance = 0.5;
  const BoundedCurvatureResult r = SmoothToTurningRadius(raw, options, *checker);
  ExpectSmoothedPath(*map, raw, r, 2.0, 0.5);
  EXPECT_EQ(r.corners, 2);
  EXPECT_LE(r.max_curvature, 0.5);
  EXPECT_LT(PathLength(r.path), 1.05 * PathLength(raw));
}

TEST(BoundedCurvatureTest, JoinsTwoCrowdedCornersTurningTheSameWay) {
  const MapPtr map = EmptyWorld();
  const auto checker = MakeCollisionChecker(*map);
  // Two 45-degree turns 0.7 apart: neither has room for a radius of 3 on its own.
  const Path raw{{2, 2, 0}, {20, 2, 0}, {20.5, 2.5, 0}, {20.5, 25, 0}};
  BoundedCurvatureOptions options;
  options.turning_radius = 3.0;
  const BoundedCurvatureResult r = SmoothToTurningRadius(raw, options, *checker);
  ExpectSmoothedPath(*map, raw, r, 3.0, 0.0);
  EXPECT_EQ(r.corners, 1);
}

TEST(BoundedCurvatureTest, MovesAVertexToMakeRoomForAnSBend) {
  // A jog between two blocks: every shortcut of its two corners hits a block, and the 5 between
  // them is too short for two turns of 84 degrees at a radius of 2; the room is further along.
  Polygon upper_left{{{0, 5}, {14, 5}, {14, 20}, {0, 20}}};
  Polygon lower_right{{{22, 0}, {40, 0}, {40, 7}, {22, 7}}};
  const MapPtr map = std::make_shared<const Map>(
      Map::Data(*ShapeWorld::Create({{0, 0}, {40, 20}}, {}, {upper_left, lower_right})));
  const auto checker = MakeCollisionChecker(*map);
  const Path raw{{2, 3, 0}, {16, 3, 0}, {16.5, 8, 0}, {38, 8, 0}};
  ASSERT_TRUE(checker->PathFree(raw, 0.5));
  ASSERT_FALSE(checker->SegmentFree(raw[0], raw[2], 0.5));
  ASSERT_FALSE(checker->SegmentFree(raw[1], raw[3], 0.5));
  ASSERT_FALSE(checker->SegmentFree(raw[0], raw[3], 0.5));
  const Point2 a(raw[0].x(), raw[0].y()), b(raw[1].x(), raw[1].y()), c(raw[2].x(), raw[2].y());
  const double needed = BezierDistanceForCurvature(
      HalfHeadingChange((a - b).normalized(), (c - b).normalized()), 0.5);
  ASSERT_GT(2 * needed, (c - b).norm()) << "the corners' curves would overlap";
  BoundedCurvatureOptions options;
  options.turning_radius = 2.0;
  options.clearance = 0.5;
  const BoundedCurvatureResult r = SmoothToTurningRadius(raw, options, *checker);
  ExpectSmoothedPath(*map, raw, r, 2.0, 0.5);
  EXPECT_LE(r.max_curvature, 0.5);
  EXPECT_LT(PathLength(r.path), 1.05 * PathLength(raw));
}

// Two long problems of random512-10-0, whose obstacles are single cells: the fleet seeds there
// keep a quarter of the way to the preferred clearance, and their smoothing moves and splits
// corners among the cells until every one has room for a radius of 2. None may leave a vertex
// that turns too little for a curve as a curve of a few nanometres (a spike in the discrete
// curvature).
TEST(BoundedCurvatureTest, FleetSeedsOnARandomGridKeepTheRadius) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/random512-10-0.map");
  absl::StatusOr<Map> loaded =
      LoadMapFile(::swarmplan::testing::BenchmarksDir() + "/movingai/random512-10-0.map");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
  const auto checker = MakeCollisionChecker(*map);
  const std::pair<Point2, Point2> problems[] = {{{93.5, 139.5}, {412.5, 184.5}},
                                                {{8.5, 467.5}, {491.5, 277.5}}};
  for (const auto& [start, goal] : problems) {
    Problem problem;
    problem.map = map;
    problem.start = {start.x(), start.y(), 0};
    problem.goal = {goal.x(), goal.y(), 0};
    problem.clearance = 0.5;
    problem.fleet.preferred_clearance = 1.5;
    problem.fleet.turning_radius = 2.0;
    absl::StatusOr<std::vector<SeedPath>> seeds = FindSeedPaths(problem, 3, StopToken());
    ASSERT_TRUE(seeds.ok()) << seeds.status();
    ASSERT_FALSE(seeds->empty());
    BoundedCurvatureOptions options;
    options.turning_radius = 2.0;
    options.clearance = 0.5;
    for (const SeedPath& seed : *seeds) {
      SCOPED_TRACE(seed.length);
      const BoundedCurvatureResult r = SmoothToTurningRadius(seed.path, options, *checker);
      ExpectSmoothedPath(*map, seed.path, r, 2.0, 0.5);
    }
  }
}

TEST(BoundedCurvatureTest, ReducesADenselySampledCurveToItsFewCorners) {
  const MapPtr map = EmptyWorld();
  const auto checker = MakeCollisionChecker(*map);
  // A spline through a zig-zag, sampled every 0.1: its own curvature is far above 1 / 2 at
  // the knots.
  CubicSpline spline;
  spline.Fit({{2, 2, 0}, {12, 20, 0}, {22, 4, 0}, {36, 26, 0}}, SplineEnd::kNotAKnot);
  Path raw;
  spline.SampleBySpacing(0.1, raw);
  ASSERT_GT(contract::LargestMengerCurvature(raw), 0.5);
  BoundedCurvatureOptions options;
  options.turning_radius = 2.0;
  const BoundedCurvatureResult r = SmoothToTurningRadius(raw, options, *checker);
  ExpectSmoothedPath(*map, raw, r, 2.0, 0.0);
  EXPECT_LT(r.corners, 40);
}

TEST(BoundedCurvatureTest, KeepsAPathThatAlreadyTurnsWideEnough) {
  const MapPtr map = EmptyWorld();
  const auto checker = MakeCollisionChecker(*map);
  // An arc of radius 5 sampled every few degrees: within 1 / 2 everywhere, so it stays as it is.
  Path raw;
  for (int i = 0; i <= 40; ++i) {
    const double a = 0.05 * i;
    raw.emplace_back(20 + 5 * std::cos(a), 10 + 5 * std::sin(a), 0);
  }
  ASSERT_LT(contract::LargestMengerCurvature(raw), 0.5);
  BoundedCurvatureOptions options;
  options.turning_radius = 2.0;
  const BoundedCurvatureResult kept = SmoothToTurningRadius(raw, options, *checker);
  EXPECT_EQ(kept.path, raw);
  EXPECT_TRUE(kept.collision_free);
  EXPECT_EQ(kept.corners_over, 0);
  // The same arc at radius 1 turns too tightly for 2: it is smoothed.
  Path tight;
  for (const Point3& p : raw) tight.emplace_back(20 + (p.x() - 20) / 5, 10 + (p.y() - 10) / 5, 0);
  const BoundedCurvatureResult smoothed = SmoothToTurningRadius(tight, options, *checker);
  EXPECT_NE(smoothed.path, tight);
}

TEST(BoundedCurvatureTest, ReportsCornersWithoutRoomInsteadOfHidingThem) {
  // A hairpin round the end of a thin wall in a corridor 4 wide cannot turn with a radius of
  // 5, wherever its corners move: the result says so.
  Polygon above{{{0, 4}, {40, 4}, {40, 30}, {0, 30}}};
  Polygon wall{{{0, 2.2}, {28, 2.2}, {28, 2.6}, {0, 2.6}}};
  const MapPtr corridor = std::make_shared<const Map>(
      Map::Data(*ShapeWorld::Create({{0, 0}, {40, 30}}, {}, {above, wall})));
  const auto checker = MakeCollisionChecker(*corridor);
  const Path raw{{2, 1.4, 0}, {29.5, 1.4, 0}, {29.5, 3.4, 0}, {2, 3.4, 0}};
  ASSERT_TRUE(checker->PathFree(raw, 0.0));
  BoundedCurvatureOptions options;
  options.turning_radius = 5.0;
  const BoundedCurvatureResult r = SmoothToTurningRadius(raw, options, *checker);
  EXPECT_TRUE(r.collision_free);
  EXPECT_GT(r.corners_over, 0);
  EXPECT_GT(r.max_curvature, 1.0 / 5.0);
  // Smooth says so too, and says the opposite where the radius fits.
  absl::StatusOr<SmoothingResult> hairpin = Smooth("bounded-curvature", *corridor, raw, 0.0, 5.0);
  ASSERT_TRUE(hairpin.ok()) << hairpin.status();
  EXPECT_FALSE(hairpin->within_turning_radius);
  const Path corner{{2, 2, 0}, {30, 2, 0}, {30, 25, 0}};
  absl::StatusOr<SmoothingResult> wide =
      Smooth("bounded-curvature", *EmptyWorld(), corner, 0.0, 5.0);
  ASSERT_TRUE(wide.ok()) << wide.status();
  EXPECT_TRUE(wide->within_turning_radius);
}

TEST(BoundedCurvatureTest, IsTheSmoothingMethodThatTakesTheTurningRadius) {
  const MapPtr map = seed_testing::TwoDoorGrid();
  const Path raw{{35.5, 3.5, 0}, {31, 13.5, 0}, {31, 16.5, 0}, {2.5, 27.5, 0}};
  const auto checker = MakeCollisionChecker(*map);
  ASSERT_TRUE(checker->PathFree(raw, 0.5));
  absl::StatusOr<SmoothingResult> smoothed = Smooth("bounded-curvature", *map, raw, 0.5, 2.0);
  ASSERT_TRUE(smoothed.ok()) << smoothed.status();
  EXPECT_TRUE(smoothed->collision_free);
  EXPECT_GE(seed_testing::Clearance(*map, smoothed->path), 0.5 - 1e-9);
  EXPECT_LE(contract::LargestMengerCurvature(smoothed->path), 0.5);
  EXPECT_LE(EvaluatePath(*map, smoothed->path, 0.5).max_curvature, 0.5);
}

}  // namespace
}  // namespace swarmplan
