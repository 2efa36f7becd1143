// The grid-node planners with init=seeded (their default) and the shared operators behind it:
// seeds rasterised to cell paths, any-angle shortcutting. Every plan joins the requested points
// exactly, is collision-free by an independent check, and is within 1.01x of the exact
// any-angle optimum; with a preferred clearance they rank by the fleet objective and end below
// their best seed; the same seed gives the same path; init=paper still runs the paper's search.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/algorithms/afsa/fish_swarm.h"
#include "core/algorithms/baselines/grid_baselines.h"
#include "core/algorithms/bfo/as_bfo.h"
#include "core/fitness/path_objective_terms.h"
#include "core/geometry/collision.h"
#include "core/grid_ops/cell_path.h"
#include "core/grid_ops/grid_path_cost.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/grid_ops/shortcut.h"
#include "core/optimum.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "core/run.h"
#include "core/seeds/seed_paths.h"
#include "core/smoothing/smoothing.h"
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

// The fleet objective: the exact path through a door grazes its post; a preferred clearance of
// 2.5 asks for the middle of the 4-cell door. Every seeded grid planner ranks by that objective,
// returns a path that keeps the hard clearance (independent check), reports the objective of
// its raw path as fitness, and ends below its best seed by the objective.
TEST(SeededGridPlannersTest, FleetObjectiveMovesThePathAwayFromTheWalls) {
  Problem problem = MakeProblem(TwoDoorGrid(), {12.5, 5.5}, {6.5, 25.5}, 0.5);
  problem.fleet.preferred_clearance = 2.5;
  // The optimum with the hard clearance hugs the walls: the seeds keep the preferred clearance
  // where the map allows, and the result must do at least as well by the objective.
  absl::StatusOr<PlanResult> hugging = Plan("exact-any-angle", problem, 1);
  ASSERT_TRUE(hugging.ok()) << hugging.status();
  absl::StatusOr<FleetTerms> hugging_terms = EvaluateFleetObjective(problem, hugging->raw_path);
  ASSERT_TRUE(hugging_terms.ok()) << hugging_terms.status();
  for (const std::string& algorithm : kGridPlanners) {
    SCOPED_TRACE(algorithm);
    absl::StatusOr<PlanResult> result = Plan(algorithm, problem, 40);
    ASSERT_TRUE(result.ok()) << result.status();
    ASSERT_TRUE(result->found);
    const Path& path = result->raw_path;
    EXPECT_EQ(path.front(), problem.start);
    EXPECT_EQ(path.back(), problem.goal);
    EXPECT_GE(seed_testing::Clearance(*problem.map, path), 0.5 - 1e-9);
    absl::StatusOr<FleetTerms> terms = EvaluateFleetObjective(problem, path);
    ASSERT_TRUE(terms.ok()) << terms.status();
    EXPECT_NEAR(result->fitness, terms->Total(), 1e-9 * terms->Total());
    ASSERT_TRUE(result->objective.has_value() && result->seed_objective.has_value());
    EXPECT_LE(result->objective->Total(), result->seed_objective->Total() * (1 + 1e-9));
    EXPECT_LT(result->objective->Total(), 0.9 * hugging_terms->Total())
        << "hugging " << hugging_terms->Total();
  }
}

TEST(GridSeedingTest, ShortcutKeepingClearanceStraightensWithoutHuggingTheWalls) {
  // A 4 x 4 block in a 30 x 30 room; the cell path goes round it at least 4 cells away.
  std::vector<std::string> rows(30, std::string(30, '.'));
  for (int y = 13; y < 17; ++y) rows[y].replace(13, 4, "####");
  const MapPtr map = testing::GridMap(rows);
  const Problem problem = MakeProblem(map, {15.5, 3.5}, {15.5, 26.5});
  absl::StatusOr<GridSpace> space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok()) << space.status();
  std::vector<Cell> around{{15, 3}};
  for (int x = 14; x >= 8; --x) around.push_back({x, 3 + (15 - x)});
  for (int y = 11; y <= 19; ++y) around.push_back({8, y});
  for (int x = 9; x <= 15; ++x) around.push_back({x, 19 + (x - 8)});
  ASSERT_EQ(around.back(), space->goal);
  const Path world = space->WorldPath(around);
  ASSERT_GE(seed_testing::Clearance(*map, world), 3.0);

  absl::StatusOr<GridPathCost> cost = [&] {
    Problem fleet = problem;
    fleet.fleet.preferred_clearance = 3.0;
    return GridPathCost::Create(fleet, *space);
  }();
  ASSERT_TRUE(cost.ok()) << cost.status();
  std::optional<Path> kept = cost->PathOf(around);
  ASSERT_TRUE(kept.has_value());
  EXPECT_LT(kept->size(), world.size()) << "straightened";
  EXPECT_LE(PathLength(*kept), PathLength(world));
  EXPECT_GE(seed_testing::Clearance(*map, *kept), 2.5) << "not pulled against the block";

  std::optional<Path> taut = AnyAnglePath(*space, around);
  ASSERT_TRUE(taut.has_value());
  EXPECT_LT(seed_testing::Clearance(*map, *taut), 0.5) << "the length's shortcut grazes it";
  EXPECT_LT(PathLength(*taut), PathLength(*kept));
}

TEST(GridSeedingTest, ShortcutKeepingClearanceMovesBendsWhereTheObjectiveFalls) {
  // Cell paths round a 6 x 6 block in a 30 x 30 room, at 1 to 5 cells from it, with a preferred
  // clearance of 3: each bend of the straightened path sits at a cell's centre, one of its
  // corners or an edge's midpoint, and the moves lower the objective against the same path
  // through the centres.
  std::vector<std::string> rows(30, std::string(30, '.'));
  for (int y = 12; y < 18; ++y) rows[y].replace(12, 6, "######");
  const MapPtr map = testing::GridMap(rows);
  Problem problem = MakeProblem(map, {14.5, 3.5}, {14.5, 26.5});
  problem.fleet.preferred_clearance = 3.0;
  absl::StatusOr<GridSpace> space = MakeGridSpace(problem, 0.0);
  ASSERT_TRUE(space.ok()) << space.status();
  absl::StatusOr<GridPathCost> cost = GridPathCost::Create(problem, *space);
  ASSERT_TRUE(cost.ok()) << cost.status();
  int moved_paths = 0;
  for (int gap = 1; gap <= 5; ++gap) {
    const int side = 11 - gap;  // the column the path runs down, left of the block
    std::vector<Cell> around{{14, 3}};
    for (int x = 13; x > side; --x) around.push_back({x, 3 + (14 - x)});
    for (int y = 3 + (14 - side); y <= 26 - (14 - side); ++y) around.push_back({side, y});
    for (int x = side + 1; x <= 14; ++x) around.push_back({x, 26 - (14 - x)});
    ASSERT_EQ(around.back(), space->goal) << "gap " << gap;
    const std::optional<Path> kept = cost->PathOf(around);
    ASSERT_TRUE(kept.has_value()) << "gap " << gap;
    EXPECT_EQ(kept->front(), problem.start);
    EXPECT_EQ(kept->back(), problem.goal);
    EXPECT_GE(seed_testing::Clearance(*map, *kept), problem.clearance);
    Path centres = *kept;
    int moved = 0;
    for (size_t i = 1; i + 1 < centres.size(); ++i) {
      const Point3 centre(std::floor(centres[i].x()) + 0.5, std::floor(centres[i].y()) + 0.5, 0);
      const Point3 offset = (centres[i] - centre).cwiseAbs();
      const bool half_cells = (offset.x() == 0.0 || offset.x() == 0.5) &&
                              (offset.y() == 0.0 || offset.y() == 0.5) && offset.z() == 0.0;
      EXPECT_TRUE(half_cells) << "gap " << gap << " vertex " << i;
      moved += !offset.isZero();
      centres[i] = centre;
    }
    absl::StatusOr<FleetTerms> kept_terms = EvaluateFleetObjective(problem, *kept);
    absl::StatusOr<FleetTerms> centre_terms = EvaluateFleetObjective(problem, centres);
    ASSERT_TRUE(kept_terms.ok() && centre_terms.ok());
    if (moved == 0) continue;
    ++moved_paths;
    EXPECT_LT(kept_terms->Total(), centre_terms->Total()) << "gap " << gap;
  }
  EXPECT_GE(moved_paths, 3);
}

// What a seeded grid planner starts from: the problem's grid space, 8-connected moves with
// line-of-sight steps, and up to three seeds (or why there are none). Neither copied nor moved:
// the seeds refer to the space.
struct SeededGrid {
  explicit SeededGrid(const Problem& problem) : space(MakeGridSpace(problem, 0.0)) {
    if (!space.ok()) {
      seeds = space.status();
      return;
    }
    moves.emplace(*space->grid, MoveRules{Neighbourhood::k8, true, 0.0});
    seeds = GridSeeds::Find(problem, *space, *moves, 3, StopToken(), &context);
  }
  SeededGrid(const SeededGrid&) = delete;
  SeededGrid& operator=(const SeededGrid&) = delete;

  absl::StatusOr<GridSpace> space;
  std::optional<GridMoves> moves;
  GridSearchContext context;
  absl::StatusOr<GridSeeds> seeds;
};

TEST(GridSeedingTest, SeedCellPathsAreValidMovesFromStartToGoal) {
  const Problem problem = MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5});
  SeededGrid grid(problem);
  ASSERT_TRUE(grid.seeds.ok()) << grid.seeds.status();
  ASSERT_EQ(grid.seeds->cell_paths().size(), 2u) << "one seed per door";
  absl::StatusOr<std::vector<SeedPath>> polylines = FindSeedPaths(problem, 3, StopToken());
  ASSERT_TRUE(polylines.ok());
  ASSERT_EQ(polylines->size(), 2u);
  EXPECT_EQ(grid.seeds->best_cost(), polylines->front().length)
      << "without preferences: the length";
  for (size_t i = 0; i < 2; ++i) {
    const std::vector<Cell>& cells = grid.seeds->cell_paths()[i];
    EXPECT_TRUE(IsValidCellPath(*grid.moves, cells));
    EXPECT_EQ(cells.front(), grid.space->start);
    EXPECT_EQ(cells.back(), grid.space->goal);
    // Shortcut, the cell path bends near the corners its seed grazes, not at them: about 0.9
    // longer per door here (3 %).
    EXPECT_LE(PathLength(*AnyAnglePath(*grid.space, cells)), (*polylines)[i].length * 1.05);
  }
}

// With a turning radius the plan returns the path after the bounded-curvature smoothing, so the
// seeded result is chosen as the plan judges it: among the best-ranked paths and the best seed,
// the one within the radius and lowest by the objective after that smoothing. The planner's best
// given here is the worst of the ranked paths: the others come back from what the ranking kept.
TEST(GridSeedingTest, TheResultIsTheBestRankedPathAfterTheSmoothing) {
  Problem problem = MakeProblem(TwoDoorGrid(), {12.5, 5.5}, {6.5, 25.5}, 0.5);
  problem.fleet.preferred_clearance = 2.5;
  problem.fleet.turning_radius = 2.0;
  SeededGrid grid(problem);
  ASSERT_TRUE(grid.seeds.ok()) << grid.seeds.status();
  absl::StatusOr<GridPathCost> cost = GridPathCost::Create(problem, *grid.space);
  ASSERT_TRUE(cost.ok()) << cost.status();

  // The plan's judgement, independently: the smoothing the plan applies, then the objective.
  struct Judged {
    bool within = false;
    double objective = 0.0;
  };
  auto judge = [&](const Path& path) {
    absl::StatusOr<SmoothingResult> smoothed =
        Smooth("bounded-curvature", *problem.map, path, problem.clearance, 2.0);
    EXPECT_TRUE(smoothed.ok() && smoothed->collision_free);
    absl::StatusOr<FleetTerms> terms = EvaluateFleetObjective(problem, smoothed->path);
    EXPECT_TRUE(terms.ok());
    return Judged{smoothed->within_turning_radius, terms->Total()};
  };
  auto better = [](const Judged& a, const Judged& b) {
    return a.within != b.within ? a.within : a.objective < b.objective;
  };

  // Paths straight through the left door at several places, ranked as a planner ranks them.
  std::vector<std::vector<Cell>> candidates;
  std::vector<double> costs;
  for (const double x : {5.5, 6.0, 6.5, 7.0}) {
    const Path through = {problem.start, Point3(x, 14.0, 0), Point3(x, 17.0, 0), problem.goal};
    std::optional<std::vector<Cell>> cells =
        SeedCellPath(*grid.space, *grid.moves, through, &grid.context);
    ASSERT_TRUE(cells.has_value());
    costs.push_back(grid.seeds->Cost(*cells));
    candidates.push_back(*std::move(cells));
  }
  const size_t worst = std::max_element(costs.begin(), costs.end()) - costs.begin();

  SearchResult result;
  grid.seeds->SetResult(candidates[worst], StopToken(), result);
  ASSERT_TRUE(result.found);
  Path expected = result.seed_path;
  Judged best = judge(expected);
  bool a_candidate_wins = false;
  for (const std::vector<Cell>& cells : candidates) {
    const std::optional<Path> path = cost->PathOf(cells);
    ASSERT_TRUE(path.has_value());
    const Judged judged = judge(*path);
    if (better(judged, best)) {
      expected = *path;
      best = judged;
      a_candidate_wins = true;
    }
  }
  ASSERT_TRUE(a_candidate_wins) << "the premise: a path through the door beats the seed";
  EXPECT_EQ(result.path, expected);
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
