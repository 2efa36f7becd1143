// The grid-node planners with init=seeded (their default) and the shared operators behind it:
// seeds rasterised to cell paths, any-angle shortcutting. Every plan joins the requested points
// exactly, is collision-free by an independent check, and is within 1.01x of the exact
// any-angle optimum; the same seed gives the same path; init=paper still runs the paper's search.

#include <memory>
#include <string>
#include <vector>

#include "core/algorithms/afsa/fish_swarm.h"
#include "core/algorithms/baselines/grid_baselines.h"
#include "core/algorithms/bfo/as_bfo.h"
#include "core/geometry/collision.h"
#include "core/grid_ops/cell_path.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/grid_ops/shortcut.h"
#include "core/optimum.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "core/run.h"
#include "core/seeds/seed_paths.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"
#include "tests/unit/plan_test_support.h"
#include "tests/unit/seed_test_maps.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using seed_testing::BlockWorld;
using seed_testing::TwoDoorGrid;

const std::vector<std::string> kGridPlanners = {"as-bfo", "afsa", "dafsa",
                                                "idafsa", "ga",   "aco-grid"};

using seed_testing::MakeProblem;

absl::StatusOr<PlanResult> Plan(const std::string& algorithm, const Problem& problem,
                                int iterations, const ParamValues& params = {}) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.params = params;
  request.problem = problem;
  request.problem.limits.max_iterations = iterations;
  testing::NullObserver observer;
  return RunPlan(DefaultRegistry(), request, StopToken(), observer);
}

void ExpectNearExactPath(const std::string& algorithm, const Problem& problem) {
  SCOPED_TRACE(algorithm);
  const Optimum optimum = ComputeOptimum(DefaultRegistry(), problem, absl::Seconds(30));
  ASSERT_TRUE(optimum.known) << optimum.reason;
  absl::StatusOr<PlanResult> result = Plan(algorithm, problem, 20);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->found);
  const Path& path = result->raw_path;
  EXPECT_EQ(path.front(), problem.start);
  EXPECT_EQ(path.back(), problem.goal);
  EXPECT_TRUE(MakeCollisionChecker(*problem.map)->PathFree(path, problem.clearance));
  const double ratio = PathLength(path) / optimum.length;
  EXPECT_GE(ratio, 1.0 - 1e-6);
  EXPECT_LE(ratio, 1.01);
  // The best seed is the incumbent from iteration 0.
  ASSERT_FALSE(result->convergence.empty());
  EXPECT_LE(result->convergence.front().best_fitness, optimum.length * (1.0 + 1e-9));
}

TEST(SeededGridPlannersTest, FindNearExactPathsOnMapsWithWalls) {
  const MapPtr two_walls = testing::GridMap(testing::TwoWallsRows());
  for (const std::string& algorithm : kGridPlanners) {
    ExpectNearExactPath(algorithm, MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5}));
    ExpectNearExactPath(algorithm, MakeProblem(two_walls, {0.5, 11.5}, {11.5, 0.5}));
    ExpectNearExactPath(algorithm, MakeProblem(BlockWorld(), {5, 15}, {35, 15}, 0.5));
  }
}

TEST(SeededGridPlannersTest, SameSeedSamePath) {
  const Problem problem = MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5});
  for (const std::string& algorithm : kGridPlanners) {
    SCOPED_TRACE(algorithm);
    absl::StatusOr<PlanResult> a = Plan(algorithm, problem, 20);
    absl::StatusOr<PlanResult> b = Plan(algorithm, problem, 20);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->raw_path, b->raw_path);
    EXPECT_EQ(a->fitness, b->fitness);
  }
}

// init=paper is the search a directly constructed planner runs (the paper's): the same path.
TEST(SeededGridPlannersTest, PaperInitialisationRunsThePapersSearch) {
  Problem problem = MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5});
  problem.limits.max_iterations = 20;
  const std::vector<std::pair<std::string, std::unique_ptr<Planner>>> direct = [] {
    std::vector<std::pair<std::string, std::unique_ptr<Planner>>> out;
    out.emplace_back("as-bfo", std::make_unique<AsBfoPlanner>(AsBfoParams{}));
    out.emplace_back("idafsa", std::make_unique<FishSwarmPlanner>(
                                   FishSwarmParams::Defaults(FishSwarmParams::Variant::kIdafsa)));
    out.emplace_back("ga", std::make_unique<GridGaPlanner>(GridGaParams{}));
    out.emplace_back("aco-grid", std::make_unique<GridAcoPlanner>(GridAcoParams{}));
    return out;
  }();
  for (const auto& [algorithm, planner] : direct) {
    SCOPED_TRACE(algorithm);
    absl::StatusOr<PlanResult> paper =
        Plan(algorithm, problem, 20, {{"init", std::string("paper")}});
    ASSERT_TRUE(paper.ok()) << paper.status();
    testing::NullObserver observer;
    absl::StatusOr<SearchResult> expected =
        planner->Solve(problem, StopToken().WithMaxIterations(20), observer);
    ASSERT_TRUE(expected.ok()) << expected.status();
    EXPECT_EQ(paper->raw_path, expected->path);
  }
}

TEST(GridSeedingTest, SeedCellPathsAreValidMovesFromStartToGoal) {
  const Problem problem = MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5});
  absl::StatusOr<GridSpace> space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok()) << space.status();
  GridMoves moves(*space->grid, MoveRules{Neighbourhood::k8, true, 0.0});
  GridSearchContext context;
  absl::StatusOr<GridSeeds> seeds =
      GridSeeds::Find(problem, *space, moves, 3, StopToken(), &context);
  ASSERT_TRUE(seeds.ok()) << seeds.status();
  ASSERT_EQ(seeds->cell_paths().size(), 2u) << "one seed per door";
  absl::StatusOr<std::vector<SeedPath>> polylines = FindSeedPaths(problem, 3, StopToken());
  ASSERT_TRUE(polylines.ok());
  ASSERT_EQ(polylines->size(), 2u);
  EXPECT_EQ(seeds->best_length(), polylines->front().length);
  for (size_t i = 0; i < 2; ++i) {
    const std::vector<Cell>& cells = seeds->cell_paths()[i];
    EXPECT_TRUE(IsValidCellPath(moves, cells));
    EXPECT_EQ(cells.front(), space->start);
    EXPECT_EQ(cells.back(), space->goal);
    // Shortcut, the cell path bends near the corners its seed grazes, not at them: about 0.9
    // longer per door here (3 %).
    EXPECT_LE(AnyAngleLength(*space, cells), (*polylines)[i].length * 1.05);
  }
}

TEST(GridSeedingTest, ShortcutStraightensAStaircaseAndRejectsABlockedSegment) {
  const MapPtr open = testing::GridMap(std::vector<std::string>(10, std::string(10, '.')));
  const Problem problem = MakeProblem(open, {0.5, 0.5}, {9.5, 5.5});
  absl::StatusOr<GridSpace> space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok());
  std::vector<Cell> staircase{{0, 0}};
  for (int x = 1; x <= 9; ++x) staircase.push_back({x, std::min(x, 5)});
  std::optional<Path> straight = AnyAnglePath(*space, staircase);
  ASSERT_TRUE(straight.has_value());
  EXPECT_EQ(straight->size(), 2u);
  EXPECT_NEAR(PathLength(*straight), (problem.goal - problem.start).norm(), 1e-9);

  const MapPtr walled = testing::GridMap(testing::TwoWallsRows());
  const Problem across = MakeProblem(walled, {2.5, 4.5}, {4.5, 4.5});
  absl::StatusOr<GridSpace> walled_space = MakeGridSpace(across, 0.0);
  ASSERT_TRUE(walled_space.ok());
  EXPECT_FALSE(AnyAnglePath(*walled_space, {{2, 4}, {4, 4}}).has_value()) << "through the wall";
}

}  // namespace
}  // namespace swarmplan
