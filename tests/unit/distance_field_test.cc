#include "core/map/distance_field.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

DistanceField RandomField(Rng& rng, int width, int height, double cell, double density) {
  std::vector<uint8_t> blocked(static_cast<size_t>(width) * height);
  for (uint8_t& b : blocked) b = rng.Uniform() < density ? 1 : 0;
  return DistanceField::FromBlockedCells(width, height, blocked, cell, Point2(-3.0, 7.0),
                                         rng.Uniform() < 0.5);
}

// Bilinear at the points SegmentKeeps and ShortfallAlong read, every one of them: a + (b - a)
// k / n, k = 0..n, n the fewest pieces no longer than half a cell.
std::vector<double> DenseSamples(const DistanceField& field, const Point2& a, const Point2& b) {
  const Point2 step = b - a;
  const int pieces =
      std::max(1, static_cast<int>(std::ceil(2.0 * step.norm() / field.cell_size())));
  std::vector<double> samples;
  for (int k = 0; k <= pieces; ++k) {
    const Point2 p = a + step * (static_cast<double>(k) / pieces);
    samples.push_back(field.Bilinear(p.x(), p.y()));
  }
  return samples;
}

// check(field, cell, a, rng) for `points` random points a on each of `fields` random 64 x 48
// fields of sparse obstacles (origin (-3, 7)).
template <typename Check>
void AtRandomPoints(uint64_t seed, int fields, int points, Check check) {
  Rng rng(seed);
  for (int trial = 0; trial < fields; ++trial) {
    const double cell = rng.Uniform(0.2, 1.5);
    const DistanceField field = RandomField(rng, 64, 48, cell, rng.Uniform(0.002, 0.05));
    for (int i = 0; i < points; ++i) {
      const Point2 a(rng.Uniform(-3.0, -3.0 + 64 * cell), rng.Uniform(7.0, 7.0 + 48 * cell));
      check(field, cell, a, rng);
    }
  }
}

// A 40 x 30 field of a random cell size and density (origin (-3, 7)), and points inside it.
struct SizedField {
  double cell;
  DistanceField field;

  Point2 RandomPoint(Rng& rng) const {
    return Point2(rng.Uniform(-3.0, -3.0 + 40 * cell), rng.Uniform(7.0, 7.0 + 30 * cell));
  }
};

// check(field, rng) on six random fields.
template <typename Check>
void OnRandomFields(uint64_t seed, Check check) {
  Rng rng(seed);
  for (int trial = 0; trial < 6; ++trial) {
    const double cell = rng.Uniform(0.1, 2.0);
    check(SizedField{cell, RandomField(rng, 40, 30, cell, rng.Uniform(0.01, 0.3))}, rng);
  }
}

TEST(DistanceFieldTest, SlopeBoundHoldsBetweenAnyTwoPoints) {
  OnRandomFields(5, [](const SizedField& f, Rng& rng) {
    ASSERT_GT(f.field.slope_bound(), 0.0);
    for (int i = 0; i < 2000; ++i) {
      const Point2 p = f.RandomPoint(rng);
      const Point2 q = p + Point2(rng.Uniform(-2, 2), rng.Uniform(-2, 2)) * f.cell;
      ASSERT_LE(std::abs(f.field.Bilinear(p.x(), p.y()) - f.field.Bilinear(q.x(), q.y())),
                f.field.slope_bound() * (p - q).norm() + 1e-9);
    }
  });
}

TEST(DistanceFieldTest, BilinearDropBoundHoldsInEveryCell) {
  OnRandomFields(11, [](const SizedField& f, Rng& rng) {
    const double bound = f.field.bilinear_drop_bound();
    ASSERT_GT(bound, 0.0);
    double closest = 1e300;  // the smallest margin seen: the bound is not loose everywhere
    for (int i = 0; i < 20000; ++i) {
      const Point2 p = f.RandomPoint(rng);
      const int cx = std::min(39, static_cast<int>((p.x() + 3.0) / f.cell));
      const int cy = std::min(29, static_cast<int>((p.y() - 7.0) / f.cell));
      const double margin = f.field.Bilinear(p.x(), p.y()) - (f.field.CellValue(cx, cy) - bound);
      ASSERT_GE(margin, 0.0) << "at (" << p.x() << ", " << p.y() << ")";
      closest = std::min(closest, margin);
    }
    EXPECT_LT(closest, 0.5 * bound);
  });
}

TEST(DistanceFieldTest, SegmentKeepsGivesTheDenseVerdict) {
  int kept = 0, refused = 0;
  AtRandomPoints(
      11, 8, 3000, [&](const DistanceField& field, double cell, const Point2& a, Rng& rng) {
        const Point2 b(rng.Uniform(-3.0, -3.0 + 64 * cell), rng.Uniform(7.0, 7.0 + 48 * cell));
        // Floors near the values the segment meets, where pruning is most tempting.
        const double floor = std::min(field.Bilinear(a.x(), a.y()), field.Bilinear(b.x(), b.y())) *
                             rng.Uniform(0.0, 1.0);
        const std::vector<double> samples = DenseSamples(field, a, b);
        const bool dense = *std::min_element(samples.begin(), samples.end()) >= floor;
        ASSERT_EQ(field.SegmentKeeps(a, b, floor), dense)
            << "a " << a.transpose() << " b " << b.transpose() << " floor " << floor;
        dense ? ++kept : ++refused;
      });
  EXPECT_GT(kept, 1000);
  EXPECT_GT(refused, 1000);
}

TEST(DistanceFieldTest, ShortfallAlongIsTheTrapezoidOfTheSamples) {
  int zero = 0, positive = 0;
  AtRandomPoints(17, 6, 2000,
                 [&](const DistanceField& field, double cell, const Point2& a, Rng& rng) {
                   const Point2 b = a + Point2(rng.Uniform(-8, 8), rng.Uniform(-8, 8)) * cell;
                   const double floor = rng.Uniform(0.0, 3.0) * cell;
                   const std::vector<double> samples = DenseSamples(field, a, b);
                   double dense = 0.0;
                   for (size_t k = 0; k < samples.size(); ++k) {
                     const double weight = k == 0 || k + 1 == samples.size() ? 0.5 : 1.0;
                     dense += weight * std::max(0.0, floor - samples[k]);
                   }
                   dense *= (b - a).norm() / static_cast<double>(samples.size() - 1);
                   const double shortfall = field.ShortfallAlong(a, b, floor);
                   ASSERT_NEAR(shortfall, dense, 1e-12 * (1.0 + dense))
                       << "a " << a.transpose() << " b " << b.transpose() << " floor " << floor;
                   shortfall == 0.0 ? ++zero : ++positive;
                 });
  EXPECT_GT(zero, 500);
  EXPECT_GT(positive, 500);
}

TEST(DistanceFieldTest, ShortfallAlongAWallIsTheGapTimesTheLength) {
  // A wall along row 0 of a 40 x 20 field of unit cells: the centres of row 3 lie 3 from the
  // wall's and read 3 - 0.5 (half a cell less), so along y = 3.5 the value is 2.5.
  std::vector<uint8_t> blocked(40 * 20, 0);
  for (int x = 0; x < 40; ++x) blocked[x] = 1;
  const DistanceField field =
      DistanceField::FromBlockedCells(40, 20, blocked, 1.0, Point2::Zero(), false);
  EXPECT_NEAR(field.ShortfallAlong(Point2(5.5, 3.5), Point2(30.5, 3.5), 4.5), 2.0 * 25.0, 1e-9);
  EXPECT_EQ(field.ShortfallAlong(Point2(5.5, 3.5), Point2(30.5, 3.5), 2.5), 0.0);
}

}  // namespace
}  // namespace swarmplan
