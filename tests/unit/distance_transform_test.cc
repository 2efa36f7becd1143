#include "core/geometry/distance_transform.h"

#include <cmath>
#include <limits>
#include <thread>
#include <vector>

#include "core/map/occupancy_grid.h"
#include "core/random.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

std::vector<double> BruteForce(int width, int height, const std::vector<uint8_t>& blocked) {
  std::vector<double> out(blocked.size(), kInf);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int by = 0; by < height; ++by) {
        for (int bx = 0; bx < width; ++bx) {
          if (!blocked[static_cast<size_t>(by) * width + bx]) continue;
          const double d = static_cast<double>((x - bx) * (x - bx) + (y - by) * (y - by));
          double& cell = out[static_cast<size_t>(y) * width + x];
          cell = std::min(cell, d);
        }
      }
    }
  }
  return out;
}

std::vector<uint8_t> RandomBlocked(Rng& rng, int width, int height, double ratio) {
  std::vector<uint8_t> blocked(static_cast<size_t>(width) * height);
  for (uint8_t& b : blocked) b = rng.Bernoulli(ratio) ? 1 : 0;
  return blocked;
}

TEST(DistanceTransformTest, MatchesBruteForceOnRandomGrids) {
  Rng rng(20261122);
  const int sizes[][2] = {{1, 1}, {1, 17}, {23, 1}, {2, 2}, {7, 5}, {32, 17}, {40, 40}, {3, 61}};
  for (const auto& size : sizes) {
    for (const double ratio : {0.01, 0.1, 0.5, 0.9}) {
      const int w = size[0], h = size[1];
      const std::vector<uint8_t> blocked = RandomBlocked(rng, w, h, ratio);
      const std::vector<double> fast = SquaredDistanceTransform(w, h, blocked);
      const std::vector<double> slow = BruteForce(w, h, blocked);
      ASSERT_EQ(fast.size(), slow.size());
      for (size_t i = 0; i < fast.size(); ++i) {
        ASSERT_EQ(fast[i], slow[i]) << w << "x" << h << " ratio " << ratio << " cell " << i;
      }
    }
  }
}

TEST(DistanceTransformTest, NothingBlockedIsInfinite) {
  for (const auto& [w, h] : {std::pair{1, 9}, std::pair{9, 1}, std::pair{6, 4}}) {
    const std::vector<double> d =
        SquaredDistanceTransform(w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h, 0));
    for (double v : d) EXPECT_EQ(v, kInf);
  }
}

TEST(DistanceTransformTest, EverythingBlockedIsZero) {
  for (const auto& [w, h] : {std::pair{1, 9}, std::pair{9, 1}, std::pair{6, 4}}) {
    const std::vector<double> d =
        SquaredDistanceTransform(w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h, 1));
    for (double v : d) EXPECT_EQ(v, 0.0);
  }
}

TEST(DistanceTransformTest, SingleBlockedCellGivesSquaredDistances) {
  std::vector<uint8_t> blocked(5 * 4, 0);
  blocked[2 * 5 + 1] = 1;  // (1, 2)
  const std::vector<double> d = SquaredDistanceTransform(5, 4, blocked);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(d[y * 5 + x], (x - 1) * (x - 1) + (y - 2) * (y - 2));
    }
  }
}

TEST(DistanceTransformTest, GridStoresWorldDistances) {
  // Blocked cell at (0, 0); resolution 0.5.
  std::vector<int8_t> cells(4 * 3, OccupancyGrid::kFree);
  cells[0] = OccupancyGrid::kOccupied;
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(4, 3, cells, 0.5);
  ASSERT_TRUE(grid.ok()) << grid.status();
  EXPECT_DOUBLE_EQ(grid->DistanceToObstacle(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(grid->DistanceToObstacle(3, 0), 1.5);
  EXPECT_DOUBLE_EQ(grid->DistanceToObstacle(3, 2), 0.5 * std::sqrt(13.0));
}

TEST(DistanceTransformTest, GridComputesItsFieldOnFirstUseOnceForAllCopies) {
  std::vector<int8_t> cells(64 * 48, OccupancyGrid::kFree);
  cells[5 * 64 + 7] = OccupancyGrid::kOccupied;
  const OccupancyGrid grid = *OccupancyGrid::Create(64, 48, cells, 0.25);
  const OccupancyGrid copy = grid;
  EXPECT_FALSE(grid.distance_field_computed());
  std::vector<const std::vector<double>*> seen(8);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < seen.size(); ++i) {
    threads.emplace_back([&, i] { seen[i] = &(i % 2 == 0 ? grid : copy).distance_field(); });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_TRUE(grid.distance_field_computed());
  EXPECT_TRUE(copy.distance_field_computed());
  for (const std::vector<double>* field : seen) EXPECT_EQ(field, seen[0]);
  EXPECT_DOUBLE_EQ(copy.DistanceToObstacle(7, 8), 0.75);
}

}  // namespace
}  // namespace swarmplan
