#include <cmath>

#include "core/algorithms/afsa/fish_swarm.h"
#include "core/geometry/collision.h"
#include "core/grid_ops/cell_path.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

using namespace swarmplan::testing;
using Variant = FishSwarmParams::Variant;

SearchResult RunFish(const FishSwarmParams& params, const Problem& problem) {
  FishSwarmPlanner planner{params};
  NullObserver none;
  absl::StatusOr<SearchResult> r = planner.Solve(problem, StopToken(), none);
  EXPECT_TRUE(r.ok()) << r.status();
  return r.ok() ? *r : SearchResult{};
}

TEST(FishSwarmTest, IdafsaFindsAShortValidPath) {
  const MapPtr map = GridMap(FishSmallRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{9, 9});
  FishSwarmPlanner planner{FishSwarmParams::Defaults(Variant::kIdafsa)};
  RecordingObserver observer;
  const SearchResult r = *planner.Solve(problem, StopToken(), observer);
  ASSERT_TRUE(r.found);
  ExpectValidGridPath(*map->grid(), r.path, Cell{0, 0}, Cell{9, 9}, Neighbourhood::k24);
  const double optimum = AStarLength(*map->grid(), Cell{0, 0}, Cell{9, 9});
  EXPECT_NEAR(r.fitness, PathLength(r.path), 1e-9);
  EXPECT_LE(r.fitness, 1.3 * optimum);  // stated factor: within 30% of 8-connected A*
  EXPECT_EQ(r.iterations, 100);         // MAXGEN: the feasible-solution set keeps searching
  ExpectMonotoneLog(observer.stats, r.iterations);
  EXPECT_TRUE(observer.stats.back().feasible);
}

TEST(FishSwarmTest, DafsaMovesAreSegmentChecked) {
  const MapPtr map = GridMap(TwoWallsRows());
  for (uint64_t seed : {1, 2, 3}) {
    const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{11, 11}, seed);
    const SearchResult r = RunFish(FishSwarmParams::Defaults(Variant::kDafsa), problem);
    if (!r.found) continue;  // dafsa may end without reaching the goal
    ExpectValidGridPath(*map->grid(), r.path, Cell{0, 0}, Cell{11, 11}, Neighbourhood::k24);
    EXPECT_LE(r.fitness, 2.5 * AStarLength(*map->grid(), Cell{0, 0}, Cell{11, 11}));
  }
}

TEST(FishSwarmTest, AfsaWithEachNeighbourhood) {
  const MapPtr map = GridMap(FishSmallRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{9, 9}, 5);
  const double optimum = AStarLength(*map->grid(), Cell{0, 0}, Cell{9, 9});
  for (Neighbourhood n : {Neighbourhood::k4, Neighbourhood::k8, Neighbourhood::k24}) {
    FishSwarmParams params = FishSwarmParams::Defaults(Variant::kAfsa);
    params.neighbourhood = n;
    params.segment_check = true;
    const SearchResult r = RunFish(params, problem);
    ASSERT_TRUE(r.found) << static_cast<int>(n);
    ExpectValidGridPath(*map->grid(), r.path, Cell{0, 0}, Cell{9, 9}, n);
    EXPECT_LE(r.fitness, 2.5 * optimum);  // stated factor for the traditional AFSA
    EXPECT_LT(r.iterations, 100);         // ends when the first fish arrives
  }
}

TEST(FishSwarmTest, UncheckedJumpsAreReportedAsCollisions) {
  // A one-cell wall the 24-neighbourhood can jump without the segment check.
  const MapPtr map = GridMap({
      "..#..",  //
      "..#..",  //
      "..#..",  //
      "..#..",  //
      ".....",  //
  });
  int jumped = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    FishSwarmParams params = FishSwarmParams::Defaults(Variant::kAfsa);
    params.neighbourhood = Neighbourhood::k24;
    const SearchResult r = RunFish(params, GridProblemFor(map, Cell{0, 0}, Cell{4, 0}, seed));
    ASSERT_FALSE(r.path.empty());
    GridMoves checked(*map->grid(), MoveRules{Neighbourhood::k24, true, 0.0});
    const bool valid = IsValidCellPath(checked, CellsOf(*map->grid(), r.path));
    EXPECT_EQ(r.found, valid);
    jumped += valid ? 0 : 1;
  }
  EXPECT_GT(jumped, 0);
}

TEST(FishSwarmTest, LongMovesKeepTheClearance) {
  const MapPtr map = GridMap(FishSmallRows());
  Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{9, 9}, 4);
  problem.clearance = 0.3;
  const SearchResult r = RunFish(FishSwarmParams::Defaults(Variant::kIdafsa), problem);
  ASSERT_TRUE(r.found);
  EXPECT_GE(MakeCollisionChecker(*map)->PathClearance(r.path), 0.3 - 1e-9);
}

TEST(FishSwarmTest, SameSeedSamePath) {
  const MapPtr map = GridMap(FishSmallRows());
  const Problem problem = GridProblemFor(map, Cell{0, 9}, Cell{9, 0}, 99);
  const FishSwarmParams params = FishSwarmParams::Defaults(Variant::kIdafsa);
  const SearchResult a = RunFish(params, problem);
  const SearchResult b = RunFish(params, problem);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.evaluations, b.evaluations);
}

TEST(FishSwarmTest, StopsWithinOneIterationOfACancel) {
  const MapPtr map = GridMap(FishSmallRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{9, 9});
  FishSwarmPlanner planner{FishSwarmParams::Defaults(Variant::kIdafsa)};
  StopToken stop;
  CancellingObserver observer(stop, 4);
  const SearchResult r = *planner.Solve(problem, stop, observer);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_EQ(observer.count, 5);
  EXPECT_EQ(r.stop_reason, StopReason::kCancelled);
}

TEST(FishSwarmTest, VariantsAreRegistered) {
  Registry registry;
  ASSERT_TRUE(registry.Register(AfsaInfo()).ok());
  ASSERT_TRUE(registry.Register(DafsaInfo()).ok());
  ASSERT_TRUE(registry.Register(IdafsaInfo()).ok());
  EXPECT_TRUE(registry.Create("afsa", {{"neighbourhood", std::string("24")}}).ok());
  EXPECT_FALSE(registry.Create("afsa", {{"neighbourhood", std::string("16")}}).ok());
  EXPECT_TRUE(registry.Create("idafsa", {}).ok());
}

}  // namespace
}  // namespace swarmplan
