#include "core/geometry/primitives.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

const std::vector<Point2> kSquare = {Point2(0, 0), Point2(2, 0), Point2(2, 2), Point2(0, 2)};
// A U opening upwards: the notch is [1, 2] x [1, 3].
const std::vector<Point2> kU = {Point2(0, 0), Point2(3, 0), Point2(3, 3), Point2(2, 3),
                                Point2(2, 1), Point2(1, 1), Point2(1, 3), Point2(0, 3)};

TEST(PrimitivesTest, PointSegmentDistance) {
  EXPECT_DOUBLE_EQ(PointSegmentDistance(Point2(1, 1), Point2(0, 0), Point2(2, 0)), 1.0);
  EXPECT_DOUBLE_EQ(PointSegmentDistance(Point2(3, 4), Point2(0, 0), Point2(0, 0)), 5.0);
  EXPECT_DOUBLE_EQ(PointSegmentDistance(Point2(-3, 4), Point2(0, 0), Point2(2, 0)), 5.0);
}

// The square-root-free pre-filter agrees with BoxDistance away from ties and never claims
// "farther" at one; negative distances are always exceeded.
TEST(PrimitivesTest, BoxesFartherThanAgreesWithBoxDistance) {
  Rng rng(17);
  auto random_box = [&] {
    const Point2 lo(rng.Uniform(-50, 50), rng.Uniform(-50, 50));
    return Bounds2{lo, lo + Point2(rng.Uniform(0, 10), rng.Uniform(0, 10))};
  };
  int farther = 0, nearer = 0;
  for (int i = 0; i < 20000; ++i) {
    const Bounds2 a = random_box(), b = random_box();
    const double distance = BoxDistance(a, b);
    const double d = i % 3 == 0 ? distance : rng.Uniform(0, 60);
    if (distance > d * (1 + 1e-9)) {
      EXPECT_TRUE(BoxesFartherThan(a, b, d)) << distance << " vs " << d;
      ++farther;
    } else {
      EXPECT_FALSE(BoxesFartherThan(a, b, d)) << distance << " vs " << d;
      ++nearer;
    }
    EXPECT_TRUE(BoxesFartherThan(a, b, -1e-9));
  }
  EXPECT_FALSE(BoxesFartherThan(Bounds2{Point2(0, 0), Point2(1, 1)},
                                Bounds2{Point2(4, 5), Point2(6, 6)},
                                std::numeric_limits<double>::infinity()));
  EXPECT_GT(farther, 5000);
  EXPECT_GT(nearer, 5000);
}

TEST(PrimitivesTest, SegmentIntersectionKinds) {
  EXPECT_EQ(SegmentIntersection(Point2(0, 0), Point2(2, 2), Point2(0, 2), Point2(2, 0)),
            SegmentContact::kProper);
  EXPECT_EQ(SegmentIntersection(Point2(0, 0), Point2(1, 1), Point2(1, 1), Point2(2, 0)),
            SegmentContact::kTouching);  // shared endpoint
  EXPECT_EQ(SegmentIntersection(Point2(0, 0), Point2(2, 0), Point2(1, 0), Point2(1, 5)),
            SegmentContact::kTouching);  // T junction
  EXPECT_EQ(SegmentIntersection(Point2(0, 0), Point2(2, 0), Point2(1, 0), Point2(3, 0)),
            SegmentContact::kTouching);  // collinear overlap
  EXPECT_EQ(SegmentIntersection(Point2(0, 0), Point2(2, 0), Point2(2.5, 0), Point2(3, 0)),
            SegmentContact::kNone);
  EXPECT_EQ(SegmentIntersection(Point2(0, 0), Point2(2, 2), Point2(0, 1), Point2(1, 2)),
            SegmentContact::kNone);
  EXPECT_DOUBLE_EQ(SegmentSegmentDistance(Point2(0, 0), Point2(2, 2), Point2(0, 1), Point2(1, 2)),
                   std::sqrt(0.5));
  EXPECT_EQ(SegmentSegmentDistance(Point2(0, 0), Point2(2, 2), Point2(0, 2), Point2(2, 0)), 0.0);
}

TEST(PrimitivesTest, PointInPolygon) {
  EXPECT_EQ(LocatePoint(Point2(1, 1), kSquare), PointLocation::kInside);
  EXPECT_EQ(LocatePoint(Point2(2, 1), kSquare), PointLocation::kBoundary);
  EXPECT_EQ(LocatePoint(Point2(2, 2), kSquare), PointLocation::kBoundary);
  EXPECT_EQ(LocatePoint(Point2(3, 1), kSquare), PointLocation::kOutside);
  EXPECT_EQ(LocatePoint(Point2(1.5, 2), kU), PointLocation::kOutside);  // in the notch
  EXPECT_EQ(LocatePoint(Point2(0.5, 2), kU), PointLocation::kInside);
  EXPECT_DOUBLE_EQ(SignedDistanceToPolygon(Point2(1.5, 1.0), kSquare), -0.5);
  EXPECT_DOUBLE_EQ(SignedDistanceToPolygon(Point2(1.5, 2.0), kU), 0.5);
}

TEST(PrimitivesTest, SegmentCrossesInterior) {
  EXPECT_TRUE(SegmentCrossesPolygonInterior(Point2(-1, 1), Point2(3, 1), kSquare));
  EXPECT_TRUE(SegmentCrossesPolygonInterior(Point2(0, 0), Point2(2, 2), kSquare));    // diagonal
  EXPECT_TRUE(SegmentCrossesPolygonInterior(Point2(1, 1), Point2(1, 1.5), kSquare));  // inside
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(-1, 0), Point2(3, 0), kSquare));  // along
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(0, 0), Point2(2, 0), kSquare));   // an edge
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(-1, 1), Point2(1, 3), kSquare));  // vertex
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(2, 2), Point2(4, 5), kSquare));
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(-1, -1), Point2(-2, 5), kSquare));
  // From tip to tip of the U's arms, across its open notch.
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(1, 3), Point2(2, 3), kU));
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(1, 1), Point2(2, 1), kU));      // notch floor
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(0, 3), Point2(3, 3), kU));      // along tops
  EXPECT_TRUE(SegmentCrossesPolygonInterior(Point2(-1, 2.5), Point2(4, 2.5), kU));  // arms
  EXPECT_TRUE(SegmentCrossesPolygonInterior(Point2(1, 3), Point2(2, 0), kU));
  EXPECT_FALSE(SegmentCrossesPolygonInterior(Point2(1.5, 4), Point2(1.5, 1), kU));
  EXPECT_TRUE(SegmentCrossesPolygonInterior(Point2(1.5, 4), Point2(1.5, 0.5), kU));
}

TEST(PrimitivesTest, ConvexFormsAgreeWithTheGeneralOnes) {
  const std::vector<Point2> hexagon = CircleToPolygon(Circle{Point2(1, 1), 1.0}, 0.1).vertices;
  Rng rng(9);
  for (int i = 0; i < 5000; ++i) {
    // Endpoints on a coarse lattice so that vertices and edges are hit exactly at times.
    const Point2 a(0.25 * rng.UniformInt(-4, 12), 0.25 * rng.UniformInt(-4, 12));
    const Point2 b = i % 3 ? Point2(0.25 * rng.UniformInt(-4, 12), 0.25 * rng.UniformInt(-4, 12))
                           : kSquare[rng.UniformInt(0, 3)];
    ASSERT_EQ(SegmentCrossesConvexInterior(a, b, kSquare),
              SegmentCrossesPolygonInterior(a, b, kSquare))
        << a.transpose() << " -> " << b.transpose();
    ASSERT_EQ(StrictlyInsideConvex(a, kSquare), LocatePoint(a, kSquare) == PointLocation::kInside);
    ASSERT_EQ(SegmentCrossesConvexInterior(a, b, hexagon),
              SegmentCrossesPolygonInterior(a, b, hexagon))
        << a.transpose() << " -> " << b.transpose();
  }
}

TEST(PrimitivesTest, SegmentPolygonDistance) {
  EXPECT_DOUBLE_EQ(SegmentPolygonDistance(Point2(3, -1), Point2(3, 3), kSquare), 1.0);
  EXPECT_DOUBLE_EQ(SegmentPolygonDistance(Point2(3, 3), Point2(4, 4), kSquare), std::sqrt(2.0));
  EXPECT_EQ(SegmentPolygonDistance(Point2(2, -1), Point2(2, 3), kSquare), 0.0);  // along edge
  EXPECT_LT(SegmentPolygonDistance(Point2(-1, 1), Point2(3, 1), kSquare), 0.0);
  EXPECT_DOUBLE_EQ(SegmentPolygonDistance(Point2(-1, 1), Point2(3, 1), kSquare), -1.0);
  EXPECT_DOUBLE_EQ(SegmentPolygonDistance(Point2(1.5, 2.5), Point2(1.5, 4), kU), 0.5);
}

TEST(PrimitivesTest, CircleToPolygonIsCircumscribedWithinTolerance) {
  const Circle c{Point2(1, 2), 3.0};
  for (const double tol : {1.0, 0.1, 1e-3}) {
    const Polygon p = CircleToPolygon(c, tol);
    const int n = static_cast<int>(p.vertices.size());
    EXPECT_GE(n, 6);
    EXPECT_EQ(
        n,
        std::max(6, static_cast<int>(std::ceil(std::numbers::pi / std::acos(3.0 / (3.0 + tol))))));
    for (int i = 0; i < n; ++i) {
      const Point2& a = p.vertices[i];
      const Point2& b = p.vertices[(i + 1) % n];
      EXPECT_NEAR(PointSegmentDistance(c.center, a, b), 3.0, 1e-12);  // edges tangent
      EXPECT_LE((a - c.center).norm(), 3.0 + tol + 1e-12);
      EXPECT_GT(Cross(b - a, c.center - a), 0.0);  // counter-clockwise
    }
  }
}

TEST(PrimitivesTest, GrowConvexPolygon) {
  const double r = 0.5, tol = 1e-3;
  const std::vector<Polygon> grown = GrowPolygon(Polygon{kSquare}, r, tol);
  ASSERT_EQ(grown.size(), 1u);
  const std::vector<Point2>& g = grown[0].vertices;
  EXPECT_TRUE(IsConvex(g));
  // Every grown vertex is within [r, r + tol] of the square; every edge at least r away.
  for (size_t i = 0; i < g.size(); ++i) {
    const double d = SignedDistanceToPolygon(g[i], kSquare);
    EXPECT_GE(d, r - 1e-12);
    EXPECT_LE(d, r + tol + 1e-12);
    const Point2& b = g[(i + 1) % g.size()];
    for (const Point2& v : kSquare) EXPECT_GE(PointSegmentDistance(v, g[i], b), r - 1e-12);
  }
  // Points within r of the square are inside the grown polygon.
  Rng rng(3);
  for (int i = 0; i < 500; ++i) {
    const Point2 p(rng.Uniform(-1, 3), rng.Uniform(-1, 3));
    if (SignedDistanceToPolygon(p, kSquare) < r) {
      EXPECT_TRUE(PointInPolygon(p, g));
    }
  }
}

TEST(PrimitivesTest, GrowNonConvexPolygonCoversTheOffsetAndNoMore) {
  const double r = 0.3, tol = 1e-3;
  const std::vector<Polygon> pieces = GrowPolygon(Polygon{kU}, r, tol);
  EXPECT_GE(pieces.size(), 2u);
  for (const Polygon& piece : pieces) EXPECT_TRUE(IsConvex(piece.vertices));
  Rng rng(4);
  for (int i = 0; i < 2000; ++i) {
    const Point2 p(rng.Uniform(-1, 4), rng.Uniform(-1, 4));
    const double d = SignedDistanceToPolygon(p, kU);
    bool covered = false;
    for (const Polygon& piece : pieces) covered |= PointInPolygon(p, piece.vertices);
    if (d < r) {
      EXPECT_TRUE(covered) << p.transpose();
    }
    if (d > r + tol + 1e-9) {
      EXPECT_FALSE(covered) << p.transpose();
    }
  }
  // Radius 0 keeps the polygon.
  const std::vector<Polygon> same = GrowPolygon(Polygon{kU}, 0.0, tol);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].vertices, kU);
}

TEST(PrimitivesTest, TriangulateCoversThePolygon) {
  const std::vector<Polygon> triangles = Triangulate(Polygon{kU});
  EXPECT_EQ(triangles.size(), kU.size() - 2);
  double area = 0.0;
  for (const Polygon& t : triangles) {
    area += 0.5 * Cross(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0]);
  }
  EXPECT_NEAR(area, 7.0, 1e-12);
}

}  // namespace
}  // namespace swarmplan
