#include <cmath>
#include <memory>

#include "bench/papers/bpso_vertices_encoding.h"
#include "bench/papers/bpso_vertices_worlds.h"
#include "bench/papers/experiments.h"
#include "bench/papers/plan_once.h"
#include "bench/papers/report_digest.h"
#include "core/geometry/obstacle_vertices.h"
#include "core/graph/visibility_graph.h"
#include "core/map/io/map_io.h"
#include "core/map/io/map_writers.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

double Optimum(const ShapeWorld& world, const Point2& start, const Point2& goal) {
  absl::StatusOr<Path> path = ShortestPathVisibility(world, start, goal, 0.0, 0.01);
  EXPECT_TRUE(path.ok()) << path.status();
  return path.ok() ? PathLength(*path) : 0.0;
}

TEST(BpsoVerticesWorldTest, HasFourVerticesPerRectangleAndBlocksTheStraightPath) {
  for (int rectangles : {2, 4, 6, 8}) {
    absl::StatusOr<ShapeWorld> world = GenerateBpsoVerticesWorld(rectangles, 4000 + rectangles);
    ASSERT_TRUE(world.ok()) << world.status();
    ASSERT_EQ(world->polygons().size(), static_cast<size_t>(rectangles));
    for (const Polygon& polygon : world->polygons()) EXPECT_EQ(polygon.vertices.size(), 4u);
    EXPECT_EQ(ObstacleVertices(*world, 0.0, 0.01).size(), static_cast<size_t>(4 * rectangles));
    const GrownObstacles grown = GrowObstacles(*world, 0.0, 0.01);
    EXPECT_FALSE(grown.Contains(BpsoVerticesStart()));
    EXPECT_FALSE(grown.Contains(BpsoVerticesGoal()));
    EXPECT_TRUE(grown.Blocks(BpsoVerticesStart(), BpsoVerticesGoal())) << rectangles;
  }
}

TEST(BpsoVerticesWorldTest, SameSeedSameWorldOtherSeedOtherWorld) {
  absl::StatusOr<ShapeWorld> a = GenerateBpsoVerticesWorld(4, 7);
  absl::StatusOr<ShapeWorld> b = GenerateBpsoVerticesWorld(4, 7);
  absl::StatusOr<ShapeWorld> c = GenerateBpsoVerticesWorld(4, 8);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  EXPECT_EQ(FormatShapesJson(*a, "w"), FormatShapesJson(*b, "w"));
  EXPECT_NE(FormatShapesJson(*a, "w"), FormatShapesJson(*c, "w"));
}

TEST(BpsoVerticesWorldTest, JsonReadsBackAsTheSameWorld) {
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(
      Bounds2{Point2(0, 0), Point2(50, 40)}, {Circle{Point2(10, 10), 2.5}},
      {Polygon{{Point2(20, 20), Point2(30, 20), Point2(30, 30.25), Point2(20, 30)}}});
  ASSERT_TRUE(world.ok());
  absl::StatusOr<Map> map = ParseMap("shapes-json", {{"w.json", FormatShapesJson(*world, "w")}});
  ASSERT_TRUE(map.ok()) << map.status();
  const ShapeWorld& read = *map->world();
  EXPECT_EQ(read.bounds().max, world->bounds().max);
  ASSERT_EQ(read.circles().size(), 1u);
  EXPECT_EQ(read.circles()[0].center, world->circles()[0].center);
  EXPECT_EQ(read.circles()[0].radius, 2.5);
  ASSERT_EQ(read.polygons().size(), 1u);
  EXPECT_EQ(read.polygons()[0].vertices, world->polygons()[0].vertices);
}

TEST(BestOrderedVertexPathTest, GoesAroundOneSquareOptimally) {
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(
      Bounds2{Point2(0, 0), Point2(100, 100)}, {},
      {Polygon{{Point2(40, 40), Point2(60, 40), Point2(60, 60), Point2(40, 60)}}});
  ASSERT_TRUE(world.ok());
  const std::optional<double> best = BestOrderedVertexPath(*world, Point2(0, 50), Point2(100, 50));
  ASSERT_TRUE(best.has_value());
  EXPECT_NEAR(*best, 2.0 * std::hypot(40.0, 10.0) + 20.0, 1e-9);
}

TEST(BestOrderedVertexPathTest, IsTheStraightLineWithoutObstaclesInTheWay) {
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(
      Bounds2{Point2(0, 0), Point2(100, 100)}, {},
      {Polygon{{Point2(40, 70), Point2(60, 70), Point2(60, 90), Point2(40, 90)}}});
  ASSERT_TRUE(world.ok());
  const std::optional<double> best = BestOrderedVertexPath(*world, Point2(0, 50), Point2(100, 50));
  ASSERT_TRUE(best.has_value());
  EXPECT_NEAR(*best, 100.0, 1e-9);
}

// Bounds the planner from below: no particle can beat the best ordered subset, which in turn
// cannot beat the visibility graph.
TEST(BestOrderedVertexPathTest, LiesBetweenTheOptimumAndWhatBpsoFinds) {
  for (int rectangles : {2, 8}) {
    absl::StatusOr<ShapeWorld> world = GenerateBpsoVerticesWorld(rectangles, 4000 + 4 * rectangles);
    ASSERT_TRUE(world.ok());
    const std::optional<double> best =
        BestOrderedVertexPath(*world, BpsoVerticesStart(), BpsoVerticesGoal());
    ASSERT_TRUE(best.has_value());
    EXPECT_GE(*best, Optimum(*world, BpsoVerticesStart(), BpsoVerticesGoal()) - 1e-6);
    PlanSpec spec;
    spec.algorithm = "bpso";
    spec.params = {{"init", std::string("paper")}};  // the paper's encoding, which the bound is of
    const MapPtr map = std::make_shared<const Map>(*world);
    for (uint64_t seed : {1, 2, 3}) {
      absl::StatusOr<PlanResult> result =
          PlanOnce(spec, map, Point3(BpsoVerticesStart().x(), BpsoVerticesStart().y(), 0),
                   Point3(BpsoVerticesGoal().x(), BpsoVerticesGoal().y(), 0), seed);
      ASSERT_TRUE(result.ok()) << result.status();
      if (result->found) {
        EXPECT_GE(result->raw_metrics.length, *best - 1e-9);
      }
    }
  }
}

// The quick report's figures (not its times, nor the discussion, which quotes time ratios) are
// fixed by the seeds: a change that moves them moves the committed tables too, so
// bench/results/bpso-vertices.md must be re-run and this digest updated with it.
TEST(BpsoVerticesReportTest, QuickReportDigestIsPinned) {
  ExperimentOptions options;
  options.quick = true;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  absl::StatusOr<std::string> report = RunBpsoVertices(options);
  ASSERT_TRUE(report.ok()) << report.status();
  EXPECT_NE(report->find("## The assistant positions"), std::string::npos);
  EXPECT_EQ(ReportDigest(WithoutTimeColumns(*report), {"## Discussion"}), "dca4b494f64daeeb");
}

}  // namespace
}  // namespace swarmplan::bench
