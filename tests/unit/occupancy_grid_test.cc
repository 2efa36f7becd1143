#include "core/map/occupancy_grid.h"

#include <cstdint>
#include <random>
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

// WithBlocked gives the grid Create would give for the same cells, including its distance
// field bit for bit, whether that field is derived from the base's or computed anew.
TEST(OccupancyGridTest, WithBlockedMatchesTheGridCreatedWithThoseCells) {
  std::mt19937_64 rng(29);
  struct Case {
    int width, height;
    double density, resolution;
  };
  for (const Case& c : {Case{37, 23, 0.1, 1.0}, Case{160, 120, 0.02, 0.25}, Case{90, 70, 0.0, 0.5},
                        Case{64, 64, 0.4, 2.0}}) {
    SCOPED_TRACE(::testing::Message() << c.width << " x " << c.height << " density " << c.density);
    std::bernoulli_distribution is_blocked(c.density);
    std::vector<int8_t> cells(static_cast<size_t>(c.width) * c.height);
    for (int8_t& v : cells) v = is_blocked(rng) ? OccupancyGrid::kUnknown : OccupancyGrid::kFree;
    const OccupancyGrid base = *OccupancyGrid::Create(c.width, c.height, cells, c.resolution);
    // A wall across the grid, single cells at the corners and at random, repeats, cells outside.
    std::vector<Cell> added;
    for (int x = 0; x < c.width; ++x) added.push_back({x, c.height / 3});
    added.push_back({0, 0});
    added.push_back({c.width - 1, c.height - 1});
    std::uniform_int_distribution<int> x_of(0, c.width - 1), y_of(0, c.height - 1);
    for (int i = 0; i < 5; ++i) added.push_back({x_of(rng), y_of(rng)});
    added.push_back(added.back());
    added.push_back({-1, 3});
    added.push_back({c.width, 0});
    for (const Cell& a : added) {
      if (a.x < 0 || a.x >= c.width || a.y < 0 || a.y >= c.height) continue;
      int8_t& v = cells[static_cast<size_t>(a.y) * c.width + a.x];
      if (v == OccupancyGrid::kFree) v = OccupancyGrid::kOccupied;
    }
    const OccupancyGrid created = *OccupancyGrid::Create(c.width, c.height, cells, c.resolution);
    for (const bool base_field_first : {false, true}) {
      SCOPED_TRACE(base_field_first ? "derived field" : "field computed anew");
      if (base_field_first) base.distance_field();
      const OccupancyGrid blocked = base.WithBlocked(added);
      EXPECT_EQ(blocked.cells(), created.cells());
      EXPECT_EQ(blocked.BlockedCount(), created.BlockedCount());
      EXPECT_EQ(blocked.distance_field(), created.distance_field());
    }
    EXPECT_NE(base.distance_field(), created.distance_field());
    const OccupancyGrid same = base.WithBlocked({{-1, -1}});
    EXPECT_EQ(&same.distance_field(), &base.distance_field());
  }
}

}  // namespace
}  // namespace swarmplan
