#include <cmath>
#include <string>

#include "bench/papers/idafsa_grids_runs.h"
#include "bench/papers/idafsa_grids_worlds.h"
#include "core/map/io/map_io.h"
#include "core/map/io/map_writers.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

OccupancyGrid GridFromAscii(const std::string& text) {
  absl::StatusOr<Map> map = ParseMap("ascii", {MapFile{"test.txt", text}});
  EXPECT_TRUE(map.ok()) << map.status();
  return *map->grid();
}

TEST(IdafsaGridsTest, GeneratedGridsAreDeterministicConnectedAndAsDense) {
  for (const IdafsaGridWorld& world : IdafsaGridWorlds()) {
    absl::StatusOr<OccupancyGrid> a = GenerateIdafsaGrid(world);
    absl::StatusOr<OccupancyGrid> b = GenerateIdafsaGrid(world);
    ASSERT_TRUE(a.ok()) << a.status();
    ASSERT_TRUE(b.ok()) << b.status();
    EXPECT_EQ(FormatAsciiMap(*a), FormatAsciiMap(*b)) << world.file;
    EXPECT_EQ(a->width(), world.size);
    EXPECT_EQ(a->height(), world.size);
    EXPECT_EQ(a->BlockedCount(), std::llround(world.obstacle_ratio * world.size * world.size));
    EXPECT_TRUE(a->IsFree(IdafsaStart(world)));
    EXPECT_TRUE(a->IsFree(IdafsaGoal(world)));
    EXPECT_TRUE(FourConnected(*a, IdafsaStart(world), IdafsaGoal(world))) << world.file;
  }
}

TEST(IdafsaGridsTest, AsciiRoundTripsThroughTheLoader) {
  const IdafsaGridWorld& world = IdafsaGridWorlds().back();
  absl::StatusOr<OccupancyGrid> grid = GenerateIdafsaGrid(world);
  ASSERT_TRUE(grid.ok());
  const std::string text = FormatAsciiMap(*grid);
  const OccupancyGrid loaded = GridFromAscii(text);
  EXPECT_EQ(loaded.cells(), grid->cells());
}

TEST(IdafsaGridsTest, FourConnectedSeesWallsAndDiagonalGaps) {
  EXPECT_TRUE(FourConnected(GridFromAscii("...\n.#.\n...\n"), Cell{0, 0}, Cell{2, 2}));
  EXPECT_FALSE(FourConnected(GridFromAscii("..#\n.#.\n#..\n"), Cell{0, 0}, Cell{2, 2}));
  EXPECT_FALSE(FourConnected(GridFromAscii("#..\n...\n...\n"), Cell{0, 0}, Cell{2, 2}));
}

TEST(IdafsaGridsTest, MoveSetOptimumUsesEachNeighbourhoodsMoves) {
  const OccupancyGrid free = GridFromAscii("...\n...\n");
  EXPECT_DOUBLE_EQ(*MoveSetOptimum(free, Neighbourhood::k4, Cell{0, 0}, Cell{2, 1}), 3.0);
  EXPECT_DOUBLE_EQ(*MoveSetOptimum(free, Neighbourhood::k8, Cell{0, 0}, Cell{2, 1}),
                   1.0 + std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(*MoveSetOptimum(free, Neighbourhood::k24, Cell{0, 0}, Cell{2, 1}),
                   std::sqrt(5.0));
  // (1, 0) blocked: the knight move crosses it and the diagonal touches its corner.
  const OccupancyGrid blocked = GridFromAscii(".#.\n...\n");
  EXPECT_DOUBLE_EQ(*MoveSetOptimum(blocked, Neighbourhood::k8, Cell{0, 0}, Cell{2, 1}), 3.0);
  EXPECT_DOUBLE_EQ(*MoveSetOptimum(blocked, Neighbourhood::k24, Cell{0, 0}, Cell{2, 1}), 3.0);
  EXPECT_FALSE(
      MoveSetOptimum(GridFromAscii(".#.\n.#.\n"), Neighbourhood::k24, Cell{0, 0}, Cell{2, 1}));
}

Path CentresOf(const OccupancyGrid& grid, const std::vector<Cell>& cells) {
  Path path;
  for (const Cell& c : cells) {
    const Point2 p = grid.CellCenter(c);
    path.push_back(Point3(p.x(), p.y(), 0.0));
  }
  return path;
}

TEST(IdafsaGridsTest, PassesThroughBlockedCellTellsJumpsFromCornerCuts) {
  const OccupancyGrid grid = GridFromAscii(".#.\n...\n");
  // A diagonal past the blocked cell only touches its corner.
  EXPECT_FALSE(PassesThroughBlockedCell(grid, CentresOf(grid, {Cell{0, 0}, Cell{1, 1}})));
  // A straight jump over it goes through its inside.
  EXPECT_TRUE(PassesThroughBlockedCell(grid, CentresOf(grid, {Cell{0, 0}, Cell{2, 0}})));
  // The knight move (0,0)-(2,1) enters the blocked cell (1,0) between (1, 0.75) and (1.5, 1).
  EXPECT_TRUE(PassesThroughBlockedCell(grid, CentresOf(grid, {Cell{0, 0}, Cell{2, 1}})));
  EXPECT_FALSE(PassesThroughBlockedCell(
      grid, CentresOf(grid, {Cell{0, 0}, Cell{0, 1}, Cell{1, 1}, Cell{2, 1}})));
  const OccupancyGrid wide = GridFromAscii("...\n.#.\n...\n");
  EXPECT_TRUE(PassesThroughBlockedCell(wide, CentresOf(wide, {Cell{0, 0}, Cell{2, 2}})));
  EXPECT_TRUE(PassesThroughBlockedCell(wide, CentresOf(wide, {Cell{0, 1}, Cell{2, 2}})));
}

TEST(IdafsaGridsTest, PaperParametersWithFeedbackGainBySizeAndOverrides) {
  const IdafsaGridWorld& small = IdafsaGridWorlds().front();
  const IdafsaGridWorld& large = IdafsaGridWorlds().back();
  const FishConfig idafsa{"idafsa", "idafsa", {{"dynamic_visual", false}}};
  ParamValues p = PaperFishParams(idafsa, small, 100);
  EXPECT_EQ(std::get<int64_t>(p.at("population")), 50);
  EXPECT_EQ(std::get<int64_t>(p.at("try_number")), 8);
  EXPECT_EQ(std::get<int64_t>(p.at("max_generations")), 100);
  EXPECT_DOUBLE_EQ(std::get<double>(p.at("visual")), 5.0);
  EXPECT_DOUBLE_EQ(std::get<double>(p.at("crowding")), 0.618);
  EXPECT_DOUBLE_EQ(std::get<double>(p.at("feedback_gain")), 17.0);
  EXPECT_FALSE(std::get<bool>(p.at("dynamic_visual")));
  EXPECT_DOUBLE_EQ(std::get<double>(PaperFishParams(idafsa, large, 10).at("feedback_gain")), 10.0);
  const FishConfig afsa{"afsa-4", "afsa", {{"neighbourhood", std::string("4")}}};
  p = PaperFishParams(afsa, large, 10);
  EXPECT_EQ(p.count("feedback_gain"), 0u);
  EXPECT_EQ(std::get<std::string>(p.at("neighbourhood")), "4");
}

}  // namespace
}  // namespace swarmplan::bench
