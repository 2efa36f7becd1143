#include "core/geometry/rasterize.h"

#include <array>
#include <cmath>
#include <numbers>

#include "core/geometry/box_overlap.h"
#include "core/geometry/shape_collision.h"
#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

int BlockedCells(const OccupancyGrid& grid) { return static_cast<int>(grid.BlockedCount()); }

// Rasterises `world` (origin at 0, 0) and checks each cell against the per-cell rule of
// box_overlap.h; returns the number of blocked cells.
int CheckEveryCell(const ShapeWorld& world, double resolution) {
  absl::StatusOr<OccupancyGrid> grid = RasterizeShapeWorld(world, resolution);
  EXPECT_TRUE(grid.ok()) << grid.status();
  if (!grid.ok()) return 0;
  for (int y = 0; y < grid->height(); ++y) {
    for (int x = 0; x < grid->width(); ++x) {
      const Point2 lo = Point2(x, y) * resolution;
      const Bounds2 square{lo, lo + Point2(resolution, resolution)};
      bool expected = false;
      for (const Circle& c : world.circles()) expected |= CircleOverlapsOpenBox(c, square);
      for (const Polygon& p : world.polygons()) {
        expected |= PolygonOverlapsOpenBox(p.vertices, square);
      }
      EXPECT_EQ(grid->IsBlocked(x, y), expected) << "cell " << x << "," << y;
      if (grid->IsBlocked(x, y) != expected) return -1;
    }
  }
  return BlockedCells(*grid);
}

TEST(RasterizeTest, AlignedSquareAndCircleBlockExactlyTheirCells) {
  const ShapeWorld world =
      *ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(10, 8)}, {Circle{Point2(6.5, 6.5), 0.5}},
                          {Polygon{{Point2(2, 2), Point2(4, 2), Point2(4, 4), Point2(2, 4)}}});
  absl::StatusOr<OccupancyGrid> grid = RasterizeShapeWorld(world, 1.0);
  ASSERT_TRUE(grid.ok()) << grid.status();
  EXPECT_EQ(grid->width(), 10);
  EXPECT_EQ(grid->height(), 8);
  EXPECT_EQ(BlockedCells(*grid), 5);
  for (const Cell c : {Cell{2, 2}, Cell{3, 2}, Cell{2, 3}, Cell{3, 3}, Cell{6, 6}}) {
    EXPECT_TRUE(grid->IsBlocked(c)) << c.x << "," << c.y;
  }
  // At half resolution the circle's cell splits in four, all overlapping the disc.
  absl::StatusOr<OccupancyGrid> fine = RasterizeShapeWorld(world, 0.5);
  ASSERT_TRUE(fine.ok());
  EXPECT_EQ(BlockedCells(*fine), 16 + 4);
}

TEST(RasterizeTest, OriginAndPartialCells) {
  const ShapeWorld world =
      *ShapeWorld::Create(Bounds2{Point2(-3, 10), Point2(7.5, 13)}, {},
                          {Polygon{{Point2(-2.9, 10.1), Point2(-2.8, 10.1), Point2(-2.8, 10.2)}}});
  absl::StatusOr<OccupancyGrid> grid = RasterizeShapeWorld(world, 1.0);
  ASSERT_TRUE(grid.ok()) << grid.status();
  EXPECT_EQ(grid->width(), 10);  // the half cell beyond x = 7 is left out
  EXPECT_EQ(grid->height(), 3);
  EXPECT_EQ(grid->origin(), Point2(-3, 10));
  EXPECT_EQ(BlockedCells(*grid), 1);
  EXPECT_TRUE(grid->IsBlocked(0, 0));
  EXPECT_FALSE(RasterizeShapeWorld(world, 20.0).ok());
  EXPECT_FALSE(RasterizeShapeWorld(world, 0.0).ok());
  EXPECT_FALSE(RasterizeShapeWorld(world, -1.0).ok());
}

TEST(RasterizeTest, ResolutionFinerThanAnIntCountIsTooManyCells) {
  // Found by fuzz_request: a world 3.8e17 cells wide at the requested resolution.
  const ShapeWorld world = *ShapeWorld::Create({{0, 0}, {3.82e11, 10}}, {}, {});
  absl::StatusOr<OccupancyGrid> grid = RasterizeShapeWorld(world, 1e-6);
  ASSERT_FALSE(grid.ok());
  EXPECT_EQ(grid.status().code(), absl::StatusCode::kResourceExhausted);
}

// The rasteriser visits only the cells along edges and fills interiors by rows; the result must
// be the per-cell rule applied to every cell and every obstacle.
TEST(RasterizeTest, EveryCellFollowsThePerCellRule) {
  Rng rng(29);
  for (int trial = 0; trial < 12; ++trial) {
    const double resolution = std::array{1.0, 0.5, 0.37, 0.25}[trial % 4];
    std::vector<Circle> circles;
    std::vector<Polygon> polygons;
    for (int i = 0; i < 5; ++i) {
      // Snapped to the cell corners half the time: centres and edges on cell boundaries.
      auto coordinate = [&](double lo, double hi) {
        const double v = rng.Uniform(lo, hi);
        return rng.Uniform() < 0.5 ? std::round(v / resolution) * resolution : v;
      };
      circles.push_back(Circle{Point2(coordinate(-1, 21), coordinate(-1, 21)),
                               i == 0 ? 1e-9 : coordinate(0.1, 3.0)});
      const double x0 = coordinate(-2, 19), y0 = coordinate(-2, 19);
      const double x1 = x0 + coordinate(0.3, 4), y1 = y0 + coordinate(0.3, 4);
      polygons.push_back(Polygon{{Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)}});
      // A star: vertices at increasing angles, random radii, so a simple non-convex polygon.
      const Point2 c(rng.Uniform(0, 20), rng.Uniform(0, 20));
      Polygon star;
      const int n = 5 + static_cast<int>(rng.UniformInt(0, 20));
      for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * (k + rng.Uniform(0, 0.5)) / n;
        star.vertices.push_back(c + rng.Uniform(0.3, 6.0) * Point2(std::cos(a), std::sin(a)));
      }
      polygons.push_back(star);
    }
    absl::StatusOr<ShapeWorld> world =
        ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(20, 20)}, circles, polygons);
    ASSERT_TRUE(world.ok()) << world.status();
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " resolution " << resolution);
    const int blocked = CheckEveryCell(*world, resolution);
    EXPECT_GT(blocked, 0);
    EXPECT_LT(blocked, 20 * 20 / (resolution * resolution));
  }
}

// Polygons that reach far outside the bounds cross every row of a tall raster, overlapping each
// other: the rows' crossings come from several edges and several polygons.
TEST(RasterizeTest, PolygonsReachingFarOutsideFollowThePerCellRule) {
  const std::vector<Polygon> polygons = {
      Polygon{{Point2(0.004, 4294967296.0), Point2(32, 1.25), Point2(2.03, 2.0)}},
      Polygon{{Point2(7.3, 950), Point2(-5, 1e9), Point2(-5, -1e9)}},
      Polygon{{Point2(4.1, 20), Point2(12, -3e6), Point2(6.6, 1999.7), Point2(5.2, 3e7)}}};
  const ShapeWorld world =
      *ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(10, 2000)}, {}, polygons);
  const int blocked = CheckEveryCell(world, 0.5);
  EXPECT_GT(blocked, 0);
  EXPECT_LT(blocked, 20 * 4000);
}

TEST(RasterizeTest, ConservativeOnRandomWorlds) {
  Rng rng(17);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Circle> circles;
    std::vector<Polygon> polygons;
    for (int i = 0; i < 6; ++i) {
      circles.push_back(
          Circle{Point2(rng.Uniform(0, 20), rng.Uniform(0, 20)), rng.Uniform(0.2, 2.0)});
      const Point2 c(rng.Uniform(0, 20), rng.Uniform(0, 20));
      Polygon p;
      const int n = 3 + static_cast<int>(rng.UniformInt(0, 4));
      for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n;
        const double r = rng.Uniform(0.5, 2.5);
        p.vertices.push_back(c + r * Point2(std::cos(a), std::sin(a)));
      }
      polygons.push_back(p);
    }
    const ShapeWorld world =
        *ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(20, 20)}, circles, polygons);
    const double resolution = 0.37;
    absl::StatusOr<OccupancyGrid> grid = RasterizeShapeWorld(world, resolution);
    ASSERT_TRUE(grid.ok()) << grid.status();
    ShapeCollisionChecker checker(world);
    for (int i = 0; i < 20000; ++i) {
      const Point2 p(rng.Uniform(0, grid->width() * resolution),
                     rng.Uniform(0, grid->height() * resolution));
      const Cell cell = grid->CellAt(p);
      if (checker.Clearance(Point3(p.x(), p.y(), 0)) < 0) {
        ASSERT_TRUE(grid->IsBlocked(cell)) << p.transpose();
      }
    }
    // Blocked cells overlap an obstacle: their squares come within a diagonal of one.
    for (int y = 0; y < grid->height(); ++y) {
      for (int x = 0; x < grid->width(); ++x) {
        if (!grid->IsBlocked(x, y)) continue;
        const Point2 centre = grid->CellCenter(Cell{x, y});
        ASSERT_LT(checker.Clearance(Point3(centre.x(), centre.y(), 0)),
                  resolution * std::sqrt(0.5));
      }
    }
  }
}

}  // namespace
}  // namespace swarmplan
