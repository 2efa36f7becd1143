#include "core/algorithms/baselines/grid_baselines.h"

#include <cmath>
#include <memory>

#include "core/path_metrics.h"
#include "core/registry.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

using namespace swarmplan::testing;

std::unique_ptr<Planner> Make(const std::string& id) {
  if (id == "ga") return std::make_unique<GridGaPlanner>(GridGaParams{});
  if (id == "aco-grid") return std::make_unique<GridAcoPlanner>(GridAcoParams{});
  return std::make_unique<GridApfPlanner>(GridApfParams{});
}

class GridBaselineTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GridBaselineTest, FindsAValidPathWithinAFactorOfAStar) {
  const MapPtr map = GridMap(TwoWallsRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{11, 11});
  std::unique_ptr<Planner> planner = Make(GetParam());
  RecordingObserver observer;
  absl::StatusOr<SearchResult> r = planner->Solve(problem, StopToken(), observer);
  ASSERT_TRUE(r.ok()) << r.status();
  ASSERT_TRUE(r->found);
  ExpectValidGridPath(*map->grid(), r->path, Cell{0, 0}, Cell{11, 11}, Neighbourhood::k8);
  EXPECT_NEAR(r->fitness, PathLength(r->path), 1e-9);
  // Stated factors: GA within 10% of A*, ACO within 50%, APF (greedy descent) within 2x.
  const double factor = GetParam() == "ga" ? 1.1 : GetParam() == "aco-grid" ? 1.5 : 2.0;
  EXPECT_LE(r->fitness, factor * AStarLength(*map->grid(), Cell{0, 0}, Cell{11, 11}));
  ExpectMonotoneLog(observer.stats, r->iterations);
}

TEST_P(GridBaselineTest, SameSeedSamePath) {
  const MapPtr map = GridMap(TwoWallsRows());
  const Problem problem = GridProblemFor(map, Cell{11, 0}, Cell{0, 11}, 17);
  NullObserver none;
  const SearchResult a = *Make(GetParam())->Solve(problem, StopToken(), none);
  const SearchResult b = *Make(GetParam())->Solve(problem, StopToken(), none);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.evaluations, b.evaluations);
}

TEST_P(GridBaselineTest, StopsWithinOneIterationOfACancel) {
  const MapPtr map = GridMap(TwoWallsRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{11, 11});
  StopToken stop;
  CancellingObserver observer(stop, 1);
  const SearchResult r = *Make(GetParam())->Solve(problem, stop, observer);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_EQ(observer.count, 2);
  EXPECT_EQ(r.stop_reason, StopReason::kCancelled);
}

INSTANTIATE_TEST_SUITE_P(Baselines, GridBaselineTest, ::testing::Values("ga", "aco-grid", "apf"));

TEST(GridApfTest, StallsInAUShapedTrapAndSaysSo) {
  const MapPtr map = GridMap({
      "...........",  //
      "...........",  //
      "..#######..",  //
      "........#..",  //
      "........#..",  //
      "..#######..",  //
      "...........",  //
  });
  const Problem problem = GridProblemFor(map, Cell{4, 3}, Cell{10, 3});
  GridApfPlanner planner{GridApfParams{}};
  NullObserver none;
  const SearchResult r = *planner.Solve(problem, StopToken(), none);
  EXPECT_FALSE(r.found);
  EXPECT_TRUE(r.path.empty());
  EXPECT_EQ(r.stop_reason, StopReason::kNone);
  EXPECT_LT(r.iterations, GridApfParams{}.max_steps);
}

TEST(GridBaselineRegistryTest, AreRegisteredWithValidDefaults) {
  Registry registry;
  ASSERT_TRUE(registry.Register(GridGaInfo()).ok());
  ASSERT_TRUE(registry.Register(GridAcoInfo()).ok());
  ASSERT_TRUE(registry.Register(GridApfInfo()).ok());
  for (const char* id : {"ga", "aco-grid", "apf"}) EXPECT_TRUE(registry.Create(id, {}).ok()) << id;
}

TEST(GridBaselineRegistryTest, GridPlannersAreInTheDefaultRegistry) {
  for (const char* id : {"as-bfo", "afsa", "dafsa", "idafsa", "bpso", "ga", "aco-grid", "apf"}) {
    const PlannerInfo* info = DefaultRegistry().Find(id);
    ASSERT_NE(info, nullptr) << id;
    EXPECT_TRUE(info->Supports(MapKind::kOccupancyGrid)) << id;
    EXPECT_TRUE(info->Supports(MapKind::kShapeWorld)) << id;
  }
}

}  // namespace
}  // namespace swarmplan
