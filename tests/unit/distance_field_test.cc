#include "core/map/distance_field.h"

#include <algorithm>
#include <cmath>
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

// The definition SegmentKeeps must agree with: every sample, read.
bool DenseKeeps(const DistanceField& field, const Point2& a, const Point2& b, double floor) {
  const Point2 step = b - a;
  const int pieces =
      std::max(1, static_cast<int>(std::ceil(2.0 * step.norm() / field.cell_size())));
  for (int k = 0; k <= pieces; ++k) {
    const Point2 p = a + step * (static_cast<double>(k) / pieces);
    if (field.Bilinear(p.x(), p.y()) < floor) return false;
  }
  return true;
}

TEST(DistanceFieldTest, SlopeBoundHoldsBetweenAnyTwoPoints) {
  Rng rng(5);
  for (int trial = 0; trial < 6; ++trial) {
    const double cell = rng.Uniform(0.1, 2.0);
    const DistanceField field = RandomField(rng, 40, 30, cell, rng.Uniform(0.01, 0.3));
    ASSERT_GT(field.slope_bound(), 0.0);
    for (int i = 0; i < 2000; ++i) {
      const Point2 p(rng.Uniform(-3.0, -3.0 + 40 * cell), rng.Uniform(7.0, 7.0 + 30 * cell));
      const Point2 q = p + Point2(rng.Uniform(-2, 2), rng.Uniform(-2, 2)) * cell;
      ASSERT_LE(std::abs(field.Bilinear(p.x(), p.y()) - field.Bilinear(q.x(), q.y())),
                field.slope_bound() * (p - q).norm() + 1e-9);
    }
  }
}

TEST(DistanceFieldTest, BilinearDropBoundHoldsInEveryCell) {
  Rng rng(11);
  for (int trial = 0; trial < 6; ++trial) {
    const double cell = rng.Uniform(0.1, 2.0);
    const DistanceField field = RandomField(rng, 40, 30, cell, rng.Uniform(0.01, 0.3));
    ASSERT_GT(field.bilinear_drop_bound(), 0.0);
    double closest = 1e300;  // the smallest margin seen: the bound is not loose everywhere
    for (int i = 0; i < 20000; ++i) {
      const Point2 p(rng.Uniform(-3.0, -3.0 + 40 * cell), rng.Uniform(7.0, 7.0 + 30 * cell));
      const int cx = std::min(39, static_cast<int>((p.x() + 3.0) / cell));
      const int cy = std::min(29, static_cast<int>((p.y() - 7.0) / cell));
      const double margin =
          field.Bilinear(p.x(), p.y()) - (field.CellValue(cx, cy) - field.bilinear_drop_bound());
      ASSERT_GE(margin, 0.0) << "at (" << p.x() << ", " << p.y() << ")";
      closest = std::min(closest, margin);
    }
    EXPECT_LT(closest, 0.5 * field.bilinear_drop_bound());
  }
}

TEST(DistanceFieldTest, SegmentKeepsGivesTheDenseVerdict) {
  Rng rng(11);
  int kept = 0, refused = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const double cell = rng.Uniform(0.2, 1.5);
    const DistanceField field = RandomField(rng, 64, 48, cell, rng.Uniform(0.002, 0.05));
    for (int i = 0; i < 3000; ++i) {
      const Point2 a(rng.Uniform(-3.0, -3.0 + 64 * cell), rng.Uniform(7.0, 7.0 + 48 * cell));
      const Point2 b(rng.Uniform(-3.0, -3.0 + 64 * cell), rng.Uniform(7.0, 7.0 + 48 * cell));
      // Floors near the values the segment meets, where pruning is most tempting.
      const double floor = std::min(field.Bilinear(a.x(), a.y()), field.Bilinear(b.x(), b.y())) *
                           rng.Uniform(0.0, 1.0);
      const bool dense = DenseKeeps(field, a, b, floor);
      ASSERT_EQ(field.SegmentKeeps(a, b, floor), dense)
          << "trial " << trial << " a " << a.transpose() << " b " << b.transpose() << " floor "
          << floor;
      dense ? ++kept : ++refused;
    }
  }
  EXPECT_GT(kept, 1000);
  EXPECT_GT(refused, 1000);
}

}  // namespace
}  // namespace swarmplan
