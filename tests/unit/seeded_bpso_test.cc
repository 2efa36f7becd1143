// bpso with init=seeded (its default): the bits choose among the obstacle vertices near the seed
// paths' corridors, with no vertex cap. Every plan joins the requested points exactly, is
// collision-free by an independent check, and is within 1.05x of the exact optimum, on small
// maps with walls and on a real map; the same seed gives the same path; init=paper still runs
// the paper's search.

#include <memory>
#include <string>

#include "core/algorithms/bpso/binary_pso.h"
#include "core/map/io/map_io.h"
#include "core/optimum.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"
#include "tests/unit/seed_test_maps.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using seed_testing::BlockWorld;
using seed_testing::TwoDoorGrid;

using seed_testing::MakeProblem;

absl::StatusOr<PlanResult> Plan(const Problem& problem, const ParamValues& params = {}) {
  PlanRequest request;
  request.algorithm = "bpso";
  request.params = params;
  request.problem = problem;
  request.problem.limits.max_iterations = 20;
  NullObserver observer;
  return RunPlan(DefaultRegistry(), request, StopToken(), observer);
}

void ExpectNearExactPath(const Problem& problem, const ParamValues& params = {}) {
  const Optimum optimum = ComputeOptimum(DefaultRegistry(), problem, absl::Seconds(30));
  ASSERT_TRUE(optimum.known) << optimum.reason;
  absl::StatusOr<PlanResult> result = Plan(problem, params);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->found);
  const Path& path = result->raw_path;
  ASSERT_GE(path.size(), 2u);
  EXPECT_EQ(path.front(), problem.start);
  EXPECT_EQ(path.back(), problem.goal);
  const double clearance = seed_testing::Clearance(*problem.map, path);
  EXPECT_GT(clearance, 0.0) << "the path touches an obstacle or leaves the map";
  EXPECT_GE(clearance, problem.clearance - 1e-9) << "the path comes closer than the clearance";
  const double ratio = PathLength(path) / optimum.length;
  EXPECT_GE(ratio, 1.0 - 1e-6);
  EXPECT_LE(ratio, 1.05);
  // The best seed is the incumbent from iteration 0, and the plan reports it.
  ASSERT_FALSE(result->convergence.empty());
  EXPECT_LE(result->convergence.front().best_fitness, 1.05 * optimum.length);
  EXPECT_TRUE(result->seed_objective.has_value());
}

TEST(SeededBpsoTest, FindsNearExactPathsOnMapsWithWalls) {
  {
    SCOPED_TRACE("two doors");
    ExpectNearExactPath(MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5}));
  }
  {
    SCOPED_TRACE("two walls");
    ExpectNearExactPath(
        MakeProblem(testing::GridMap(testing::TwoWallsRows()), {0.5, 11.5}, {11.5, 0.5}));
  }
  {
    SCOPED_TRACE("block world, clearance 0.5");
    ExpectNearExactPath(MakeProblem(BlockWorld(), {5, 15}, {35, 15}, 0.5));
  }
}

// The paper's cap refuses this map; the seeded search has none.
TEST(SeededBpsoTest, HasNoVertexCap) {
  const Problem problem = MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5});
  EXPECT_EQ(
      Plan(problem, {{"init", std::string("paper")}, {"max_vertices", int64_t{2}}}).status().code(),
      absl::StatusCode::kFailedPrecondition);
  ExpectNearExactPath(problem, {{"max_vertices", int64_t{2}}});
}

TEST(SeededBpsoTest, FindsNearExactPathsOnARealMap) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/Berlin_0_256.map");
  absl::StatusOr<Map> map = LoadMapFile(testing::BenchmarksDir() + "/movingai/Berlin_0_256.map");
  ASSERT_TRUE(map.ok()) << map.status();
  ExpectNearExactPath(
      MakeProblem(std::make_shared<const Map>(*std::move(map)), {10.5, 176.5}, {254.5, 226.5}));
}

TEST(SeededBpsoTest, SameSeedSamePath) {
  for (const Problem& problem : {MakeProblem(TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5}),
                                 MakeProblem(BlockWorld(), {5, 15}, {35, 15}, 0.5)}) {
    absl::StatusOr<PlanResult> a = Plan(problem);
    absl::StatusOr<PlanResult> b = Plan(problem);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->raw_path, b->raw_path);
    EXPECT_EQ(a->fitness, b->fitness);
  }
}

// init=paper is the search a directly constructed planner runs (the paper's): the same path.
TEST(SeededBpsoTest, PaperInitialisationRunsThePapersSearch) {
  const Problem problem = MakeProblem(BlockWorld(), {5, 15}, {35, 15});
  absl::StatusOr<std::unique_ptr<Planner>> paper =
      DefaultRegistry().Create("bpso", {{"init", std::string("paper")}});
  ASSERT_TRUE(paper.ok()) << paper.status();
  BinaryPsoPlanner direct{BinaryPsoParams{}};
  NullObserver none;
  absl::StatusOr<SearchResult> a = (*paper)->Solve(problem, StopToken(), none);
  absl::StatusOr<SearchResult> b = direct.Solve(problem, StopToken(), none);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->path, b->path);
  EXPECT_EQ(a->fitness, b->fitness);
  EXPECT_TRUE(a->seed_path.empty());
}

}  // namespace
}  // namespace swarmplan
