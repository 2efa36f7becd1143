#include "core/geometry/collision.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/geometry/grid_collision.h"
#include "core/geometry/primitives.h"
#include "core/geometry/shape_collision.h"
#include "core/geometry/terrain_collision.h"
#include "core/map/generate.h"
#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

Point3 P(double x, double y, double z = 0.0) { return Point3(x, y, z); }

// Rows given top line = row 0 (y = 0); '#' blocked, '.' free.
OccupancyGrid GridFrom(const std::vector<std::string>& rows, double resolution = 1.0,
                       Point2 origin = Point2::Zero()) {
  const int w = static_cast<int>(rows.front().size());
  const int h = static_cast<int>(rows.size());
  std::vector<int8_t> cells;
  for (const std::string& row : rows) {
    for (char c : row) cells.push_back(c == '#' ? OccupancyGrid::kOccupied : OccupancyGrid::kFree);
  }
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(w, h, cells, resolution, origin);
  EXPECT_TRUE(grid.ok()) << grid.status();
  return *std::move(grid);
}

OccupancyGrid RandomGrid(Rng& rng, int w, int h, double ratio) {
  std::vector<int8_t> cells(static_cast<size_t>(w) * h);
  for (int8_t& c : cells)
    c = rng.Bernoulli(ratio) ? OccupancyGrid::kOccupied : OccupancyGrid::kFree;
  return *OccupancyGrid::Create(w, h, cells);
}

std::vector<Point2> Square(int x, int y) {
  return {Point2(x, y), Point2(x + 1, y), Point2(x + 1, y + 1), Point2(x, y + 1)};
}

// Exact distance (cells, resolution 1) from a point to the nearest blocked square.
double BrutePointClearance(const OccupancyGrid& g, const Point2& p) {
  double best = kInf;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (!g.IsBlocked(x, y)) continue;
      const double dx = std::max({0.0, x - p.x(), p.x() - (x + 1)});
      const double dy = std::max({0.0, y - p.y(), p.y() - (y + 1)});
      best = std::min(best, std::hypot(dx, dy));
    }
  }
  return best;
}

// Exact distance from a segment to the nearest blocked square (0 when touching).
double BruteSegmentClearance(const OccupancyGrid& g, const Point2& a, const Point2& b) {
  double best = kInf;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (!g.IsBlocked(x, y)) continue;
      best = std::min(best, std::max(0.0, SegmentPolygonDistance(a, b, Square(x, y))));
    }
  }
  return best;
}

// --- Occupancy grid --------------------------------------------------------------------------

TEST(GridCollisionTest, CornerTouchingBlockedCellIsNotFree) {
  const OccupancyGrid grid = GridFrom({"...", ".#.", "..."});
  GridCollisionChecker checker(grid);
  EXPECT_FALSE(checker.SegmentFree(P(0.5, 0.5), P(1.0, 1.0), 0.0));  // ends on the corner
  EXPECT_TRUE(checker.SegmentFree(P(0.5, 0.5), P(0.99, 0.99), 0.0));
  EXPECT_FALSE(checker.SegmentFree(P(0.5, 1.5), P(1.5, 0.5), 0.0));  // through the corner
  EXPECT_TRUE(checker.SegmentFree(P(0.5, 1.5), P(1.4, 0.5), 0.0));   // passes below-left
  EXPECT_FALSE(checker.SegmentFree(P(0.5, 2.5), P(2.5, 0.5), 0.0));  // crosses the cell
  EXPECT_TRUE(checker.SegmentFree(P(0.5, 0.5), P(2.5, 0.5), 0.0));
  EXPECT_FALSE(checker.SegmentFree(P(0.5, 1.0), P(2.5, 1.0), 0.0));  // along its bottom edge
}

TEST(GridCollisionTest, NoSqueezingBetweenDiagonalObstacles) {
  const OccupancyGrid squeeze = GridFrom({".#", "#."});
  EXPECT_FALSE(GridCollisionChecker(squeeze).SegmentFree(P(0.5, 0.5), P(1.5, 1.5), 0.0));
  const OccupancyGrid one_side = GridFrom({".#", ".."});
  EXPECT_FALSE(GridCollisionChecker(one_side).SegmentFree(P(0.5, 0.5), P(1.5, 1.5), 0.0));
  const OccupancyGrid open = GridFrom({"..", ".."});
  EXPECT_TRUE(GridCollisionChecker(open).SegmentFree(P(0.5, 0.5), P(1.5, 1.5), 0.0));
}

TEST(GridCollisionTest, AlongAWall) {
  const OccupancyGrid grid = GridFrom({"......", "######", "......"});
  GridCollisionChecker checker(grid);
  EXPECT_TRUE(checker.SegmentFree(P(0.5, 0.5), P(5.5, 0.5), 0.0));
  EXPECT_TRUE(checker.SegmentFree(P(0.0, 0.999), P(6.0, 0.999), 0.0));
  EXPECT_FALSE(checker.SegmentFree(P(0.0, 1.0), P(6.0, 1.0), 0.0));
  EXPECT_FALSE(checker.SegmentFree(P(0.5, 0.5), P(0.5, 2.5), 0.0));
  // With clearance: the wall is 0.5 below the centre line of row 0.
  EXPECT_TRUE(checker.SegmentFree(P(0.5, 0.5), P(5.5, 0.5), 0.45));
  EXPECT_FALSE(checker.SegmentFree(P(0.5, 0.5), P(5.5, 0.5), 0.55));
  EXPECT_DOUBLE_EQ(checker.SegmentClearance(P(0.5, 0.5), P(5.5, 0.5)), 0.5);
  EXPECT_DOUBLE_EQ(checker.SegmentClearance(P(0.5, 0.5), P(0.5, 0.5)), 0.5);
  EXPECT_LT(checker.SegmentClearance(P(0.5, 0.5), P(0.5, 2.5)), 0.0);  // through the wall
  EXPECT_LE(checker.SegmentClearance(P(0.0, 1.0), P(6.0, 1.0)), 0.0);  // along its edge
}

TEST(GridCollisionTest, MapEdgesAndOutside) {
  const OccupancyGrid grid = GridFrom({"...", "..."});
  GridCollisionChecker checker(grid);
  EXPECT_TRUE(checker.SegmentFree(P(0, 0), P(3, 0), 0.0));  // the edge is inside the map
  EXPECT_TRUE(checker.SegmentFree(P(0, 0), P(3, 2), 0.0));
  EXPECT_FALSE(checker.SegmentFree(P(-0.1, 0.5), P(2, 0.5), 0.0));
  EXPECT_FALSE(checker.SegmentFree(P(0.5, 0.5), P(0.5, 2.01), 0.0));
  EXPECT_EQ(checker.Clearance(P(3.01, 1)), -kInf);
  EXPECT_EQ(checker.Clearance(P(1, 1)), kInf);  // nothing blocked
  EXPECT_EQ(checker.SegmentClearance(P(0.5, 0.5), P(2.5, 1.5)), kInf);
  EXPECT_EQ(checker.SegmentClearance(P(0.5, 0.5), P(3.5, 1.5)), -kInf);
}

TEST(GridCollisionTest, ClearanceToSquaresNotCentres) {
  // Blocked (2, 0) at resolution 0.5, origin (10, 20): its square is [11, 11.5] x [20, 20.5].
  const OccupancyGrid grid = GridFrom({"..#.", "....", "...."}, 0.5, Point2(10, 20));
  GridCollisionChecker checker(grid);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(10.25, 20.25)), 0.75);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(10.75, 20.75)), std::hypot(0.25, 0.25));
  EXPECT_DOUBLE_EQ(checker.Clearance(P(11.25, 21.25)), 0.75);
  EXPECT_NEAR(checker.Clearance(P(11.2, 20.2)), -0.2, 1e-12);
  EXPECT_LT(checker.Clearance(P(11.0, 20.25)), 0.0);  // on the blocked square's edge
  EXPECT_FALSE(checker.PointFree(P(11.2, 20.2), 0.0));
  EXPECT_TRUE(checker.SegmentFree(P(10.25, 20.25), P(10.25, 21.25), 0.7));
  EXPECT_FALSE(checker.SegmentFree(P(10.25, 20.25), P(11.75, 20.75), 0.0));
}

TEST(GridCollisionTest, ClearanceIsExactNearAndConservativeFar) {
  Rng rng(7);
  for (int trial = 0; trial < 6; ++trial) {
    const OccupancyGrid grid = RandomGrid(rng, 30, 20, trial < 3 ? 0.02 : 0.2);
    GridCollisionChecker checker(grid);
    for (int i = 0; i < 400; ++i) {
      const Point2 p(rng.Uniform(0, 30), rng.Uniform(0, 20));
      const double got = checker.Clearance(P(p.x(), p.y()));
      if (grid.IsBlocked(grid.CellAt(p))) {
        ASSERT_LT(got, 0.0);
        continue;
      }
      const double exact = BrutePointClearance(grid, p);
      ASSERT_LE(got, exact + 1e-12) << p.transpose();
      if (exact <= 1.85) {  // the scan radius covers every blocked square that can be nearest
        ASSERT_NEAR(got, exact, 1e-12) << p.transpose();
      } else {
        ASSERT_GE(got, exact - std::sqrt(2.0) - 1e-9) << p.transpose();
      }
    }
  }
}

TEST(GridCollisionTest, TraversalMatchesExactGeometry) {
  Rng rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const OccupancyGrid grid = RandomGrid(rng, 24, 18, 0.05 + 0.05 * trial);
    GridCollisionChecker checker(grid);
    int free_count = 0;
    for (int i = 0; i < 400; ++i) {
      const Point2 a(rng.Uniform(0, 24), rng.Uniform(0, 18));
      const Point2 b = i % 2 ? Point2(rng.Uniform(0, 24), rng.Uniform(0, 18))
                             : Point2(a + Point2(rng.Uniform(-3, 3), rng.Uniform(-3, 3)))
                                   .cwiseMax(Point2(0, 0))
                                   .cwiseMin(Point2(24, 18));
      const double exact = BruteSegmentClearance(grid, a, b);
      const bool free = checker.SegmentFree(P(a.x(), a.y()), P(b.x(), b.y()), 0.0);
      if (exact == 0.0) {
        ASSERT_FALSE(free) << a.transpose() << " -> " << b.transpose();
      }
      if (exact > 1e-7) {
        ASSERT_TRUE(free) << a.transpose() << " -> " << b.transpose();
      }
      free_count += free;
    }
    EXPECT_GT(free_count, 20);
  }
}

// Short segments whose ends lie on a quarter-cell lattice run along borders and through corners,
// where touching a blocked square decides: every verdict is the exact one.
TEST(GridCollisionTest, ShortSegmentsOnCellBordersMatchExactGeometry) {
  Rng rng(17);
  for (int trial = 0; trial < 4; ++trial) {
    const OccupancyGrid grid = RandomGrid(rng, 20, 16, 0.1 + 0.1 * trial);
    GridCollisionChecker checker(grid);
    int free_count = 0, blocked_count = 0;
    for (int i = 0; i < 3000; ++i) {
      const Point2 a(0.25 * rng.UniformInt(1, 79), 0.25 * rng.UniformInt(1, 63));
      const Point2 b = (a + 0.25 * Point2(rng.UniformInt(-6, 6), rng.UniformInt(-6, 6)))
                           .cwiseMax(Point2(0.25, 0.25))
                           .cwiseMin(Point2(19.75, 15.75));
      const bool free = checker.TraversalFree(a, b);
      ASSERT_EQ(free, BruteSegmentClearance(grid, a, b) > 0.0)
          << a.transpose() << " -> " << b.transpose();
      free_count += free;
      blocked_count += !free;
    }
    EXPECT_GT(free_count, 100);
    EXPECT_GT(blocked_count, 100);
  }
}

// SegmentFree and SegmentFreeByScan against the brute-force distance to every blocked square.
TEST(GridCollisionTest, SegmentChecksWithClearanceAreExact) {
  Rng rng(13);
  for (int trial = 0; trial < 4; ++trial) {
    const OccupancyGrid grid = RandomGrid(rng, 24, 18, 0.04);
    GridCollisionChecker checker(grid);
    for (int i = 0; i < 300; ++i) {
      const Point2 a(rng.Uniform(0, 24), rng.Uniform(0, 18));
      const Point2 b = Point2(a + Point2(rng.Uniform(-5, 5), rng.Uniform(-5, 5)))
                           .cwiseMax(Point2(0, 0))
                           .cwiseMin(Point2(24, 18));
      const double exact = BruteSegmentClearance(grid, a, b);
      const double c = rng.Uniform(0.05, 1.5);
      if (std::abs(exact - c) > 1e-9) {
        ASSERT_EQ(checker.SegmentFree(P(a.x(), a.y()), P(b.x(), b.y()), c), exact >= c)
            << a.transpose() << " -> " << b.transpose() << " clearance " << c;
        ASSERT_EQ(checker.SegmentFreeByScan(P(a.x(), a.y()), P(b.x(), b.y()), c), exact >= c)
            << a.transpose() << " -> " << b.transpose() << " clearance " << c;
      }
      const double got = checker.SegmentClearance(P(a.x(), a.y()), P(b.x(), b.y()));
      if (exact > 0.0) {
        ASSERT_NEAR(got, exact, 1e-12) << a.transpose() << " -> " << b.transpose();
      } else {
        ASSERT_LE(got, 0.0) << a.transpose() << " -> " << b.transpose();
      }
    }
  }
}

// The exact segment clearance against dense sampling with the exact point-to-square distance,
// on dense and sparse grids (long segments far from every obstacle), at a resolution and
// origin other than 1 and 0.
TEST(GridCollisionTest, SegmentClearanceMatchesDenseSampling) {
  Rng rng(17);
  const double resolution = 0.5;
  const Point2 origin(3, -2);
  for (int trial = 0; trial < 6; ++trial) {
    const int w = 24, h = 16;
    const OccupancyGrid cells = RandomGrid(rng, w, h, trial % 2 ? 0.003 : 0.15);
    const OccupancyGrid grid = *OccupancyGrid::Create(w, h, cells.cells(), resolution, origin);
    GridCollisionChecker checker(grid);
    for (int i = 0; i < 40; ++i) {
      const Point2 a(rng.Uniform(0, w), rng.Uniform(0, h));
      const Point2 b = i % 3 ? Point2(rng.Uniform(0, w), rng.Uniform(0, h)) : a;
      const Point3 wa = P(origin.x() + a.x() * resolution, origin.y() + a.y() * resolution);
      const Point3 wb = P(origin.x() + b.x() * resolution, origin.y() + b.y() * resolution);
      const double got = checker.SegmentClearance(wa, wb);
      constexpr int kSamples = 1000;
      double sampled = kInf;
      for (int k = 0; k <= kSamples; ++k) {
        sampled = std::min(sampled, BrutePointClearance(cells, a + (b - a) * k / kSamples));
      }
      sampled *= resolution;
      const double spacing = (b - a).norm() * resolution / kSamples;
      if (sampled > spacing) {
        // Clearance is 1-Lipschitz: the true minimum is within half a spacing of the samples'.
        ASSERT_LE(got, sampled + 1e-12) << a.transpose() << " -> " << b.transpose();
        ASSERT_GE(got, sampled - spacing / 2 - 1e-12) << a.transpose() << " -> " << b.transpose();
      }
      if (sampled == 0.0) {
        ASSERT_LE(got, 0.0) << a.transpose() << " -> " << b.transpose();
      }
    }
  }
}

// --- Shape world -----------------------------------------------------------------------------

ShapeWorld TestWorld() {
  return *ShapeWorld::Create(Bounds2{Point2(0, 0), Point2(10, 10)}, {Circle{Point2(3, 3), 1.0}},
                             {Polygon{{Point2(6, 6), Point2(8, 6), Point2(8, 8), Point2(6, 8)}}});
}

TEST(ShapeCollisionTest, ExactPointDistances) {
  const ShapeWorld world = TestWorld();
  ShapeCollisionChecker checker(world);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(5, 3)), 1.0);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(3, 3)), -1.0);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(9, 7)), 1.0);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(7, 7)), -1.0);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(9, 9)), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(checker.Clearance(P(6, 7)), 0.0);
  EXPECT_EQ(checker.Clearance(P(11, 5)), -kInf);
  EXPECT_EQ(checker.Clearance(P(5, -0.1)), -kInf);
}

TEST(ShapeCollisionTest, ExactSegmentDistances) {
  const ShapeWorld world = TestWorld();
  ShapeCollisionChecker checker(world);
  EXPECT_DOUBLE_EQ(checker.SegmentClearance(P(0, 5), P(10, 5)), 1.0);
  EXPECT_NEAR(checker.SegmentClearance(P(0, 10), P(10, 0)), std::sqrt(2.0), 1e-12);  // (6, 6)
  EXPECT_LT(checker.SegmentClearance(P(5, 7), P(9, 7)), 0.0);  // crosses the square
  EXPECT_FALSE(checker.SegmentFree(P(5, 7), P(9, 7), 0.0));
  EXPECT_FALSE(checker.SegmentFree(P(6, 6), P(8, 8), 0.0));     // its diagonal
  EXPECT_LT(checker.SegmentClearance(P(0, 3), P(10, 3)), 0.0);  // crosses the circle
  EXPECT_FALSE(checker.SegmentFree(P(0, 3), P(10, 3), 0.0));
  EXPECT_EQ(checker.SegmentClearance(P(0, 3), P(11, 3)), -kInf);
}

TEST(ShapeCollisionTest, TouchingIsFreeAtZeroClearanceOnly) {
  const ShapeWorld world = TestWorld();
  ShapeCollisionChecker checker(world);
  EXPECT_TRUE(checker.SegmentFree(P(5, 5), P(6, 6), 0.0));   // ends on a vertex
  EXPECT_TRUE(checker.SegmentFree(P(6, 6), P(8, 6), 0.0));   // along an edge
  EXPECT_FALSE(checker.SegmentFree(P(4, 4), P(9, 9), 0.0));  // through two vertices
  EXPECT_FALSE(checker.SegmentFree(P(5, 4), P(7, 8), 0.0));  // via a vertex into the inside
  EXPECT_TRUE(checker.SegmentFree(P(5, 7), P(7, 5), 0.0));   // touches the corner (6, 6)
  EXPECT_FALSE(checker.SegmentFree(P(5, 7), P(7, 5), 0.01));
  EXPECT_TRUE(checker.SegmentFree(P(0, 4), P(6, 4), 0.0));  // tangent to the circle
  EXPECT_FALSE(checker.SegmentFree(P(6, 6), P(8, 6), 0.1));
  EXPECT_TRUE(checker.SegmentFree(P(6, 5.9), P(8, 5.9), 0.1 - 1e-12));
}

TEST(ShapeCollisionTest, SegmentClearanceMatchesDenseSampling) {
  const ShapeWorld world = TestWorld();
  ShapeCollisionChecker checker(world);
  Rng rng(5);
  for (int i = 0; i < 300; ++i) {
    const Point3 a = P(rng.Uniform(0, 10), rng.Uniform(0, 10));
    const Point3 b = P(rng.Uniform(0, 10), rng.Uniform(0, 10));
    const double got = checker.SegmentClearance(a, b);
    double sampled = kInf;
    constexpr int kSamples = 2000;
    for (int k = 0; k <= kSamples; ++k) {
      sampled = std::min(sampled, checker.Clearance(a + (b - a) * k / kSamples));
    }
    const double spacing = (b - a).norm() / kSamples;
    if (sampled >= 0) {
      ASSERT_LE(got, sampled + 1e-12);
      ASSERT_GE(got, sampled - spacing) << a.transpose() << " -> " << b.transpose();
    } else {
      ASSERT_LT(got, 0.0) << a.transpose() << " -> " << b.transpose();
    }
  }
}

// Random worlds of circles and convex polygons plus one non-convex polygon: the exact segment
// clearance against dense sampling of the exact point clearance.
TEST(ShapeCollisionTest, SegmentClearanceMatchesDenseSamplingOnRandomWorlds) {
  Rng rng(23);
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    RandomWorldOptions options;
    options.bounds = Bounds2{Point2(0, 0), Point2(30, 20)};
    options.obstacle_ratio = 0.15;
    options.min_radius = 1.0;
    options.max_radius = 3.0;
    absl::StatusOr<ShapeWorld> random = RandomShapeWorld(options, seed);
    ASSERT_TRUE(random.ok()) << random.status();
    std::vector<Polygon> polygons = random->polygons();
    polygons.push_back(Polygon{{Point2(20, 2), Point2(26, 2), Point2(26, 8), Point2(24, 8),
                                Point2(24, 4), Point2(20, 4)}});  // an L
    const ShapeWorld world = *ShapeWorld::Create(options.bounds, random->circles(), polygons);
    ShapeCollisionChecker checker(world);
    for (int i = 0; i < 80; ++i) {
      const Point3 a = P(rng.Uniform(0, 30), rng.Uniform(0, 20));
      const Point3 b = i % 4 ? P(rng.Uniform(0, 30), rng.Uniform(0, 20)) : a;
      const double got = checker.SegmentClearance(a, b);
      constexpr int kSamples = 2000;
      double sampled = kInf;
      for (int k = 0; k <= kSamples; ++k) {
        sampled = std::min(sampled, checker.Clearance(a + (b - a) * k / kSamples));
      }
      const double spacing = (b - a).norm() / kSamples;
      if (sampled > spacing) {
        ASSERT_LE(got, sampled + 1e-12) << a.transpose() << " -> " << b.transpose();
        ASSERT_GE(got, sampled - spacing / 2 - 1e-12) << a.transpose() << " -> " << b.transpose();
      }
      if (sampled < 0.0) {
        ASSERT_LT(got, 0.0) << a.transpose() << " -> " << b.transpose();
      }
    }
  }
}

// --- Terrain ---------------------------------------------------------------------------------

// The terrains below have cells of 2 world units with the lower-left corner at (10, 20): the
// centre of cell (i, j) is at (11 + 2 i, 21 + 2 j). W places a point by its cell coordinates.
constexpr double kCell = 2.0;
const Point2 kOrigin(10.0, 20.0);
Point3 W(double i, double j, double z) {
  return Point3(kOrigin.x() + (i + 0.5) * kCell, kOrigin.y() + (j + 0.5) * kCell, z);
}

TEST(TerrainCollisionTest, HeightAboveBilinearGroundInWorldCoordinates) {
  // h = x + 2 y (cell indices) on a 3 x 3 grid; ceiling 20.
  std::vector<double> h;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) h.push_back(x + 2.0 * y);
  }
  const Terrain terrain = *Terrain::Create(3, 3, h, kCell, kOrigin, 20.0);
  EXPECT_EQ(terrain.CellCentre(1, 2), Point2(13, 25));
  EXPECT_EQ(terrain.ToCell(Point2(12, 24)), Point2(0.5, 1.5));
  EXPECT_EQ(terrain.min_xy(), Point2(11, 21));
  EXPECT_EQ(terrain.max_xy(), Point2(15, 25));
  TerrainCollisionChecker checker(terrain);
  EXPECT_DOUBLE_EQ(checker.Clearance(P(13, 23, 10)), 7.0);  // the centre of cell (1, 1)
  EXPECT_DOUBLE_EQ(checker.Clearance(W(0.5, 0.5, 5)), 3.5);
  EXPECT_DOUBLE_EQ(checker.Clearance(W(2, 2, 5)), -1.0);
  EXPECT_EQ(checker.Clearance(W(2.1, 1, 10)), -kInf);
  EXPECT_EQ(checker.Clearance(W(1, -0.1, 10)), -kInf);
  EXPECT_EQ(checker.Clearance(P(10.5, 23, 10)), -kInf);  // inside cell 0 but outside its centre
  EXPECT_EQ(checker.Clearance(W(1, 1, 20.5)), -kInf);
  EXPECT_DOUBLE_EQ(checker.SegmentClearance(W(0, 0, 10), W(2, 2, 10)), 4.0);
  EXPECT_TRUE(checker.SegmentFree(W(0, 0, 10), W(2, 2, 10), 4.0));
  EXPECT_FALSE(checker.SegmentFree(W(0, 0, 10), W(2, 2, 10), 4.1));
}

TEST(TerrainCollisionTest, RidgeAndNoData) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Ridge of height 10 along x = 2; no data at (4, 0).
  std::vector<double> h(5 * 3, 0.0);
  for (int y = 0; y < 3; ++y) h[y * 5 + 2] = 10.0;
  h[4] = nan;
  const Terrain terrain = *Terrain::Create(5, 3, h, kCell, kOrigin, 30.0);
  TerrainCollisionChecker checker(terrain);
  EXPECT_FALSE(checker.SegmentFree(W(0, 1, 5), W(4, 1, 5), 0.0));
  EXPECT_TRUE(checker.SegmentFree(W(0, 1, 11), W(4, 1, 11), 0.5));
  EXPECT_DOUBLE_EQ(checker.SegmentClearance(W(0, 1, 11), W(4, 1, 11)), 1.0);
  EXPECT_EQ(checker.Clearance(W(3.5, 0.5, 11)), -kInf);  // a corner has no data
  EXPECT_DOUBLE_EQ(checker.Clearance(W(3.5, 1.5, 11)), 11.0);
  EXPECT_FALSE(checker.SegmentFree(W(0, 0, 11), W(4, 0, 11), 0.0));
  EXPECT_EQ(checker.SegmentClearance(W(0, 0, 11), W(4, 0, 11)), -kInf);
  EXPECT_EQ(checker.SegmentClearance(W(0, 1, 11), W(4, 1, 31)), -kInf);  // above the ceiling
}

TEST(TerrainCollisionTest, SegmentClearanceIsExactInsideACell) {
  // A saddle: corners 0 and 0 on one diagonal, 1 and 1 on the other. Along the first diagonal
  // the ground is 2t - 2t^2, highest (0.5) in the middle, where no end of the segment is.
  const Terrain terrain = *Terrain::Create(2, 2, {0, 1, 1, 0}, kCell, kOrigin, 5.0);
  TerrainCollisionChecker checker(terrain);
  EXPECT_NEAR(checker.SegmentClearance(W(0, 0, 0.6), W(1, 1, 0.6)), 0.1, 1e-15);
  EXPECT_FALSE(checker.SegmentFree(W(0, 0, 0.6), W(1, 1, 0.6), 0.11));
  EXPECT_TRUE(checker.SegmentFree(W(0, 0, 0.6), W(1, 1, 0.6), 0.1 - 1e-12));
  // Rising with the ground: the clearance is z - g = 0.6 + 0.5 t - 2t + 2t^2, least at t = 3/8.
  EXPECT_NEAR(checker.SegmentClearance(W(0, 0, 0.6), W(1, 1, 1.1)), 0.6 - 9.0 / 32, 1e-15);
}

TEST(TerrainCollisionTest, SegmentClearanceMatchesDenseSamplingOnRandomTerrains) {
  Rng rng(17);
  for (int trial = 0; trial < 20; ++trial) {
    const int width = 6, depth = 5;
    std::vector<double> h(width * depth);
    for (double& v : h) v = rng.Uniform(0.0, 4.0);
    const Terrain terrain = *Terrain::Create(width, depth, h, kCell, kOrigin, 20.0);
    TerrainCollisionChecker checker(terrain);
    for (int s = 0; s < 20; ++s) {
      const Point3 a = W(rng.Uniform(0, width - 1), rng.Uniform(0, depth - 1), rng.Uniform(0, 8));
      const Point3 b = W(rng.Uniform(0, width - 1), rng.Uniform(0, depth - 1), rng.Uniform(0, 8));
      const double exact = checker.SegmentClearance(a, b);
      double sampled = kInf;
      const int samples = 20000;
      for (int k = 0; k <= samples; ++k) {
        sampled = std::min(sampled, checker.Clearance(a + (b - a) * (double(k) / samples)));
      }
      // Never above a sample; the samples come within their spacing's reach of it.
      EXPECT_LE(exact, sampled + 1e-12) << "trial " << trial << " segment " << s;
      EXPECT_NEAR(exact, sampled, 2e-3) << "trial " << trial << " segment " << s;
    }
  }
}

// --- Shared ----------------------------------------------------------------------------------

TEST(CollisionCheckerTest, MakesTheCheckerOfTheMapKind) {
  const Map grid_map(GridFrom({"..", ".."}));
  const Map world_map(TestWorld());
  const Map terrain_map(*Terrain::Create(2, 2, {0, 0, 0, 0}));
  EXPECT_NE(dynamic_cast<const GridCollisionChecker*>(MakeCollisionChecker(grid_map).get()),
            nullptr);
  EXPECT_NE(dynamic_cast<const ShapeCollisionChecker*>(MakeCollisionChecker(world_map).get()),
            nullptr);
  EXPECT_NE(dynamic_cast<const TerrainCollisionChecker*>(MakeCollisionChecker(terrain_map).get()),
            nullptr);
}

TEST(CollisionCheckerTest, PathsAndEmptyPaths) {
  const Map map(TestWorld());
  const auto checker = MakeCollisionChecker(map);
  EXPECT_FALSE(checker->PathFree({}, 0.0));
  EXPECT_EQ(checker->PathClearance({}), -kInf);
  EXPECT_TRUE(checker->PathFree({P(1, 9)}, 0.5));
  EXPECT_DOUBLE_EQ(checker->PathClearance({P(5, 3)}), 1.0);
  const Path around = {P(1, 1), P(1, 5), P(5, 5), P(5, 1)};
  EXPECT_TRUE(checker->PathFree(around, 0.9));
  EXPECT_NEAR(checker->PathClearance(around), 1.0, 1e-12);
  EXPECT_FALSE(checker->PathFree({P(1, 1), P(5, 5), P(7, 7)}, 0.0));
}

}  // namespace
}  // namespace swarmplan
