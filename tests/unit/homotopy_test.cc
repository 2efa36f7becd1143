#include "core/geometry/homotopy.h"

#include <gtest/gtest.h>

#include "tests/unit/seed_test_maps.h"

namespace swarmplan {
namespace {

TEST(HomotopyTest, PathsThroughDifferentDoorsAreSeparated) {
  const MapPtr map = seed_testing::TwoDoorGrid();  // doors at x in [4, 8) and [30, 34), y = 15
  const Path left{{20.5, 5.5, 0}, {6, 15.5, 0}, {20.5, 25.5, 0}};
  const Path right{{20.5, 5.5, 0}, {32, 15.5, 0}, {20.5, 25.5, 0}};
  const Path right_again{{20.5, 5.5, 0}, {31, 14, 0}, {33, 17, 0}, {20.5, 25.5, 0}};
  EXPECT_TRUE(SeparatedByObstacle(*map, left, right));
  EXPECT_TRUE(SeparatedByObstacle(*map, right, left));
  EXPECT_FALSE(SeparatedByObstacle(*map, right, right_again));
  EXPECT_FALSE(SeparatedByObstacle(*map, left, left));
}

TEST(HomotopyTest, AboveAndBelowABlockAreSeparatedInAWorld) {
  const MapPtr map = seed_testing::BlockWorld();  // block [10, 30] x [12, 18]
  const Path below{{5, 15, 0}, {10, 11, 0}, {30, 11, 0}, {35, 15, 0}};
  const Path above{{5, 15, 0}, {10, 19, 0}, {30, 19, 0}, {35, 15, 0}};
  const Path far_below{{5, 15, 0}, {20, 2, 0}, {35, 15, 0}};
  EXPECT_TRUE(SeparatedByObstacle(*map, below, above));
  EXPECT_FALSE(SeparatedByObstacle(*map, below, far_below));
}

}  // namespace
}  // namespace swarmplan
