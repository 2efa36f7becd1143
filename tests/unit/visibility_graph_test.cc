#include "core/graph/visibility_graph.h"

#include <cmath>
#include <string>

#include "core/geometry/collision.h"
#include "core/geometry/obstacle_vertices.h"
#include "core/geometry/rasterize.h"
#include "core/geometry/shape_collision.h"
#include "core/graph/theta_star.h"
#include "core/map/io/map_io.h"
#include "core/path_metrics.h"
#include "core/random.h"
#include "gtest/gtest.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

ShapeWorld World(std::vector<Circle> circles, std::vector<Polygon> polygons,
                 Bounds2 bounds = Bounds2{Point2(0, -5), Point2(10, 5)}) {
  absl::StatusOr<ShapeWorld> world =
      ShapeWorld::Create(bounds, std::move(circles), std::move(polygons));
  EXPECT_TRUE(world.ok()) << world.status();
  return *std::move(world);
}

Polygon Box(double x0, double y0, double x1, double y1) {
  return Polygon{{Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)}};
}

const Polygon kU{{Point2(0, 0), Point2(3, 0), Point2(3, 3), Point2(2, 3), Point2(2, 1),
                  Point2(1, 1), Point2(1, 3), Point2(0, 3)}};

// Checks a path with the exact checker and returns its length.
double CheckedLength(const ShapeWorld& world, const Path& path, double clearance) {
  ShapeCollisionChecker checker(world);
  EXPECT_TRUE(checker.PathFree(path, clearance)) << "clearance " << clearance;
  return PathLength(path);
}

TEST(VisibilityGraphTest, AroundOneSquare) {
  const ShapeWorld world = World({}, {Box(4, -1, 6, 1)});
  absl::StatusOr<Path> path = ShortestPathVisibility(world, Point2(0, 0), Point2(10, 0), 0, 1e-3);
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_EQ(path->size(), 4u);
  EXPECT_NEAR(CheckedLength(world, *path, 0.0), 2.0 + 2.0 * std::sqrt(17.0), 1e-9);
}

TEST(VisibilityGraphTest, AroundOneSquareWithClearance) {
  const ShapeWorld world = World({}, {Box(4, -1, 6, 1)});
  const double c = 0.5;
  absl::StatusOr<Path> path = ShortestPathVisibility(world, Point2(0, 0), Point2(10, 0), c, 1e-4);
  ASSERT_TRUE(path.ok()) << path.status();
  // Tangent from the start to the arc of radius c about (4, 1), the arc, the top, and back.
  const double d = std::sqrt(17.0);
  const double arc = std::atan2(1.0, 4.0) + std::asin(c / d);
  const double exact = 2.0 * (std::sqrt(d * d - c * c) + c * arc) + 2.0;
  const double length = CheckedLength(world, *path, c);
  EXPECT_GE(length, exact - 1e-6);
  EXPECT_LE(length, exact + 1e-3);
}

TEST(VisibilityGraphTest, StartInTheSlackOfACoarseArc) {
  // With a coarse tolerance the grown corner at (4, 1) is a single miter point 0.707 away; a
  // start 0.55 from the corner keeps the clearance 0.5 although it is inside the grown square.
  const ShapeWorld world = World({}, {Box(4, -1, 6, 1)});
  const Point2 start = Point2(4, 1) + 0.55 * Point2(-1, 1).normalized();
  absl::StatusOr<Path> path = ShortestPathVisibility(world, start, Point2(10, 0), 0.5, 0.4);
  ASSERT_TRUE(path.ok()) << path.status();
  CheckedLength(world, *path, 0.5);
  absl::StatusOr<Path> back = ShortestPathVisibility(world, Point2(10, 0), start, 0.5, 0.4);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_NEAR(PathLength(*back), PathLength(*path), 1e-9);
}

TEST(VisibilityGraphTest, AroundOneCircle) {
  const ShapeWorld world = World({Circle{Point2(5, 0), 1.0}}, {});
  absl::StatusOr<Path> path = ShortestPathVisibility(world, Point2(0, 0), Point2(10, 0), 0, 1e-5);
  ASSERT_TRUE(path.ok()) << path.status();
  const double exact = 2.0 * (std::sqrt(24.0) + std::asin(0.2));
  const double length = CheckedLength(world, *path, 0.0);
  EXPECT_GE(length, exact - 1e-6);
  EXPECT_LE(length, exact + 1e-3);
}

TEST(VisibilityGraphTest, OutOfANonConvexNotch) {
  const ShapeWorld world = World({}, {kU}, Bounds2{Point2(-2, -3), Point2(5, 5)});
  absl::StatusOr<Path> path =
      ShortestPathVisibility(world, Point2(1.5, 2), Point2(1.5, -2), 0.0, 1e-3);
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_NEAR(CheckedLength(world, *path, 0.0), std::sqrt(1.25) + 1.0 + 3.0 + 2.5, 1e-9);
  // With clearance the notch (1 wide) still admits 0.2 on both sides.
  absl::StatusOr<Path> wide =
      ShortestPathVisibility(world, Point2(1.5, 2), Point2(1.5, -2), 0.2, 1e-3);
  ASSERT_TRUE(wide.ok()) << wide.status();
  EXPECT_GT(CheckedLength(world, *wide, 0.2), 7.6);
  EXPECT_LT(PathLength(*wide), 9.0);
  // A start in the notch closer than the clearance to its walls is refused.
  EXPECT_EQ(
      ShortestPathVisibility(world, Point2(1.5, 2), Point2(1.5, -2), 0.6, 1e-3).status().code(),
      absl::StatusCode::kFailedPrecondition);
}

TEST(VisibilityGraphTest, DirectLineAndErrors) {
  const ShapeWorld world = World({}, {Box(4, -1, 6, 1)});
  absl::StatusOr<Path> direct = ShortestPathVisibility(world, Point2(0, 2), Point2(10, 2), 0, 1);
  ASSERT_TRUE(direct.ok());
  EXPECT_EQ(direct->size(), 2u);
  EXPECT_EQ(ShortestPathVisibility(world, Point2(5, 0), Point2(10, 2), 0, 1).status().code(),
            absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(ShortestPathVisibility(world, Point2(0, 0), Point2(11, 2), 0, 1).status().code(),
            absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(ShortestPathVisibility(world, Point2(0, 0), Point2(9, 2), -1, 1).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ShortestPathVisibility(world, Point2(0, 0), Point2(9, 2), 0, 0).status().code(),
            absl::StatusCode::kInvalidArgument);
}

TEST(VisibilityGraphTest, EnclosedStartIsNotFound) {
  // Four walls around (2, 0), overlapping at the corners.
  const ShapeWorld world = World(
      {}, {Box(0.5, -2, 3.5, -1.5), Box(0.5, 1.5, 3.5, 2), Box(0.5, -2, 1, 2), Box(3, -2, 3.5, 2)});
  EXPECT_EQ(ShortestPathVisibility(world, Point2(2, 0), Point2(8, 0), 0, 1e-3).status().code(),
            absl::StatusCode::kNotFound);
  // A gap of 0.5 in the right wall lets it out without clearance, not with 0.3.
  const ShapeWorld gap =
      World({}, {Box(0.5, -2, 3.5, -1.5), Box(0.5, 1.5, 3.5, 2), Box(0.5, -2, 1, 2),
                 Box(3, -2, 3.5, -0.25), Box(3, 0.25, 3.5, 2)});
  EXPECT_TRUE(ShortestPathVisibility(gap, Point2(2, 0), Point2(8, 0), 0, 1e-3).ok());
  EXPECT_EQ(ShortestPathVisibility(gap, Point2(2, 0), Point2(8, 0), 0.3, 1e-3).status().code(),
            absl::StatusCode::kNotFound);
}

TEST(ObstacleVerticesTest, SortedByXThenYAndOutsideOtherPieces) {
  // Two overlapping squares: the corners inside the other square are not vertices.
  const ShapeWorld world = World({}, {Box(1, 1, 3, 3), Box(2, 2, 4, 4)});
  const std::vector<Point2> v = ObstacleVertices(world, 0.0, 1e-3);
  const std::vector<Point2> expected = {Point2(1, 1), Point2(1, 3), Point2(2, 4),
                                        Point2(3, 1), Point2(4, 2), Point2(4, 4)};
  EXPECT_EQ(v, expected);
  const std::vector<Point2> grown = ObstacleVertices(world, 0.5, 0.1);
  EXPECT_TRUE(std::is_sorted(grown.begin(), grown.end(), [](const Point2& a, const Point2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  }));
  ShapeCollisionChecker checker(world);
  for (const Point2& p : grown) {
    EXPECT_GE(checker.Clearance(Point3(p.x(), p.y(), 0)), 0.5);
    EXPECT_LE(checker.Clearance(Point3(p.x(), p.y(), 0)), 0.6 + 1e-6);
  }
}

// On the real polygon worlds: the path is collision-free and no longer than Theta* on a
// conservative rasterisation of the same world (whose paths are valid in the world too).
TEST(VisibilityGraphTest, RealWorldsBeatThetaStarOnTheirRaster) {
  SWARMPLAN_REQUIRE_BENCHMARKS("polygons");
  for (const std::string name : {"parking1", "parking3", "warehouse", "warehouse2"}) {
    SCOPED_TRACE(name);
    absl::StatusOr<Map> map =
        LoadMapFile(testing::BenchmarksDir() + "/polygons/" + name + ".geojson");
    ASSERT_TRUE(map.ok()) << map.status();
    const ShapeWorld& world = *map->world();
    const double resolution = std::max(world.bounds().Width(), world.bounds().Height()) / 200;
    absl::StatusOr<OccupancyGrid> grid = RasterizeShapeWorld(world, resolution);
    ASSERT_TRUE(grid.ok()) << grid.status();
    const Map grid_map(*grid);
    const auto grid_checker = MakeCollisionChecker(grid_map);
    Rng rng(42);
    int solved = 0;
    for (int trial = 0; trial < 6; ++trial) {
      const double clearance = trial % 2 ? 0.0 : 2.0 * resolution;
      GridSearchOptions options;
      options.clearance = clearance;
      auto random_cell = [&] {
        for (;;) {
          const Cell c{static_cast<int>(rng.UniformInt(0, grid->width() - 1)),
                       static_cast<int>(rng.UniformInt(0, grid->height() - 1))};
          if (CellUsable(*grid, c, clearance)) return c;
        }
      };
      const Cell from = random_cell();
      const Cell to = random_cell();
      const GridSearchResult theta = ThetaStar(*grid, *grid_checker, from, to, options);
      if (!theta.found) continue;
      const Point2 start = grid->CellCenter(from);
      const Point2 goal = grid->CellCenter(to);
      absl::StatusOr<Path> path = ShortestPathVisibility(world, start, goal, clearance, 1e-4);
      ASSERT_TRUE(path.ok()) << path.status();
      const double length = CheckedLength(world, *path, clearance);
      EXPECT_LE(length, theta.length + 1e-3) << "trial " << trial;
      if (::testing::Test::HasFailure()) {
        ADD_FAILURE() << name << " " << start.transpose() << " " << goal.transpose() << " c "
                      << clearance;
        return;
      }
      ++solved;
    }
    EXPECT_GE(solved, 3);
  }
}

}  // namespace
}  // namespace swarmplan
