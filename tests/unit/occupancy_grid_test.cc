#include "core/map/occupancy_grid.h"

#include <cstdint>
#include <vector>

#include "absl/strings/str_cat.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

// Every int8 value at one cell of a 7 x 5 grid: -1 (unknown) and 0..100 are accepted, -1 and
// values from the blocked threshold up block the cell, anything else is refused by name.
TEST(OccupancyGridTest, EveryCellValueIsCheckedAndClassified) {
  for (int value = -128; value <= 127; ++value) {
    std::vector<int8_t> cells(35, OccupancyGrid::kFree);
    cells[2 * 7 + 4] = static_cast<int8_t>(value);
    absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(7, 5, cells);
    if (value < -1 || value > 100) {
      ASSERT_FALSE(grid.ok()) << value;
      EXPECT_EQ(grid.status().code(), absl::StatusCode::kInvalidArgument);
      EXPECT_THAT(grid.status().message(), HasSubstr(absl::StrCat("cell 4,2 has value ", value)));
      continue;
    }
    ASSERT_TRUE(grid.ok()) << value << ": " << grid.status();
    const bool blocked = value == -1 || value >= OccupancyGrid::kBlockedThreshold;
    EXPECT_EQ(grid->IsBlocked(4, 2), blocked) << value;
    EXPECT_EQ(grid->BlockedCount(), blocked ? 1 : 0) << value;
  }
}

TEST(OccupancyGridTest, TheFirstBadCellIsNamed) {
  std::vector<int8_t> cells(35, OccupancyGrid::kOccupied);
  cells[3 * 7 + 1] = 101;
  cells[4 * 7 + 6] = -5;
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(7, 5, cells);
  ASSERT_FALSE(grid.ok());
  EXPECT_THAT(grid.status().message(), HasSubstr("cell 1,3 has value 101"));
}

TEST(OccupancyGridTest, BlockedCountOnALargeGrid) {
  // Long enough for the vectorised loops' main bodies and their tails.
  const int w = 1031, h = 17;
  std::vector<int8_t> cells(static_cast<size_t>(w) * h);
  int64_t expected = 0;
  for (size_t i = 0; i < cells.size(); ++i) {
    cells[i] = static_cast<int8_t>(static_cast<int>(i * 37 % 102) - 1);
    expected += cells[i] == -1 || cells[i] >= OccupancyGrid::kBlockedThreshold;
  }
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(w, h, cells);
  ASSERT_TRUE(grid.ok()) << grid.status();
  EXPECT_EQ(grid->BlockedCount(), expected);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int8_t v = cells[static_cast<size_t>(y) * w + x];
      ASSERT_EQ(grid->IsBlocked(x, y), v == -1 || v >= OccupancyGrid::kBlockedThreshold);
    }
  }
}

}  // namespace
}  // namespace swarmplan
