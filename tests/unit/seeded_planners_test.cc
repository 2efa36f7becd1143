// The waypoint swarm planners with init=seeded (their default): on generated maps and on the
// shared Moving AI maps, every plan joins the requested points exactly, is collision-free by the
// contract test's independent checker, and is never longer than 1.05x the exact optimum; the
// same seed gives the same path; init=paper still runs the paper's search.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/fitness/path_objective_terms.h"
#include "core/map/io/map_io.h"
#include "core/optimum.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"
#include "tests/unit/contract_checks.h"
#include "tests/unit/plan_test_support.h"
#include "tests/unit/seed_test_maps.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using seed_testing::BlockWorld;
using seed_testing::Clearance;
using seed_testing::CrossingX;
using seed_testing::TwoDoorGrid;

const std::vector<std::string> kSeededPlanners = {"bso", "aem-bso", "aem-bso-linear", "pso", "ba"};

absl::StatusOr<PlanResult> Plan(const std::string& algorithm, const MapPtr& map,
                                const Point2& start, const Point2& goal, int iterations,
                                const ParamValues& params = {}, double clearance = 0.0) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.params = params;
  request.problem.map = map;
  request.problem.start = Point3(start.x(), start.y(), 0);
  request.problem.goal = Point3(goal.x(), goal.y(), 0);
  request.problem.clearance = clearance;
  request.problem.limits.max_iterations = iterations;
  request.problem.seed = 11;
  testing::NullObserver observer;
  return RunPlan(DefaultRegistry(), request, StopToken(), observer);
}

// A plan across TwoDoorGrid, from below the wall to above it.
PlanRequest TwoDoorRequest(const std::string& algorithm, int iterations) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.problem.map = TwoDoorGrid();
  request.problem.start = Point3(20.5, 5.5, 0);
  request.problem.goal = Point3(20.5, 25.5, 0);
  request.problem.limits.max_iterations = iterations;
  return request;
}

void ExpectGoodPath(const std::string& algorithm, const MapPtr& map, const Point2& start,
                    const Point2& goal, int iterations, double clearance = 0.0) {
  SCOPED_TRACE(algorithm);
  Problem problem;
  problem.map = map;
  problem.start = Point3(start.x(), start.y(), 0);
  problem.goal = Point3(goal.x(), goal.y(), 0);
  problem.clearance = clearance;
  const Optimum optimum = ComputeOptimum(DefaultRegistry(), problem, absl::Seconds(30));
  ASSERT_TRUE(optimum.known) << optimum.reason;
  absl::StatusOr<PlanResult> result = Plan(algorithm, map, start, goal, iterations, {}, clearance);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->found);
  const Path& path = result->raw_path;
  EXPECT_EQ(path.front(), problem.start);
  EXPECT_EQ(path.back(), problem.goal);
  EXPECT_GT(Clearance(*map, path), 0.0);
  EXPECT_GE(Clearance(*map, path), clearance - 1e-9);
  const double ratio = PathLength(path) / optimum.length;
  EXPECT_GE(ratio, 1.0 - 1e-6);
  EXPECT_LE(ratio, 1.05);
  ::testing::Test::RecordProperty(algorithm + "_ratio", std::to_string(ratio));
}

TEST(SeededPlannersTest, FindNearOptimalPathsOnGeneratedMaps) {
  for (const std::string& algorithm : kSeededPlanners) {
    ExpectGoodPath(algorithm, TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5}, 30);
    ExpectGoodPath(algorithm, BlockWorld(), {5, 15}, {35, 15}, 30, 0.5);
  }
}

TEST(SeededPlannersTest, FindNearOptimalPathsOnMovingAiMaps) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/Berlin_0_256.map");
  const std::string dir = ::swarmplan::testing::BenchmarksDir() + "/movingai/";
  for (const char* name : {"Berlin_0_256", "8room_000"}) {
    SCOPED_TRACE(name);
    const std::string file = dir + name + ".map";
    if (!std::filesystem::exists(file)) continue;
    absl::StatusOr<Map> loaded = LoadMapFile(file);
    ASSERT_TRUE(loaded.ok()) << loaded.status();
    const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
    absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(file + ".scen");
    ASSERT_TRUE(scenarios.ok()) << scenarios.status();
    const Scenario& s = scenarios->back();
    const OccupancyGrid& grid = *map->grid();
    for (const std::string& algorithm : kSeededPlanners) {
      ExpectGoodPath(algorithm, map, grid.CellCenter(s.start), grid.CellCenter(s.goal), 20);
    }
  }
}

// With a preferred clearance the swarm moves the exact path (which grazes the door's corners)
// away from the walls: a lower objective than its seed's and a larger clearance.
TEST(SeededPlannersTest, PreferredClearanceMovesThePathOffTheWalls) {
  // The optimum without the preferred clearance hugs the walls; the seeds keep the preferred
  // clearance where the map allows, and the result must do at least as well by the objective.
  PlanRequest exact = TwoDoorRequest("exact-any-angle", 1);
  exact.problem.fleet.preferred_clearance = 1.5;
  testing::NullObserver exact_observer;
  absl::StatusOr<PlanResult> hugging =
      RunPlan(DefaultRegistry(), exact, StopToken(), exact_observer);
  ASSERT_TRUE(hugging.ok()) << hugging.status();
  EXPECT_LT(Clearance(*exact.problem.map, hugging->raw_path), 1e-6);
  absl::StatusOr<FleetTerms> hugging_terms =
      EvaluateFleetObjective(exact.problem, hugging->raw_path);
  ASSERT_TRUE(hugging_terms.ok()) << hugging_terms.status();
  for (const std::string& algorithm : kSeededPlanners) {
    SCOPED_TRACE(algorithm);
    PlanRequest request = TwoDoorRequest(algorithm, 150);
    request.problem.fleet.preferred_clearance = 1.5;
    request.problem.seed = 3;
    testing::NullObserver observer;
    absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
    ASSERT_TRUE(result.ok()) << result.status();
    ASSERT_TRUE(result->found);
    ASSERT_FALSE(result->convergence.empty());
    EXPECT_LE(result->fitness, result->convergence.front().best_fitness);
    EXPECT_LT(result->fitness, 0.97 * hugging_terms->Total());
    EXPECT_GT(Clearance(*request.problem.map, result->raw_path), 0.2);
  }
}

TEST(SeededPlannersTest, AlternativesTakeTheOtherCorridors) {
  for (const std::string& algorithm : kSeededPlanners) {
    SCOPED_TRACE(algorithm);
    PlanRequest request = TwoDoorRequest(algorithm, 40);
    request.problem.alternatives = 3;
    testing::NullObserver observer;
    absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, StopToken(), observer);
    ASSERT_TRUE(result.ok()) << result.status();
    ASSERT_TRUE(result->found);
    ASSERT_EQ(result->alternatives.size(), 1u) << "two doors: the result's and one more";
    const PlanResult::Alternative& other = result->alternatives[0];
    EXPECT_EQ(other.path.front(), request.problem.start);
    EXPECT_EQ(other.path.back(), request.problem.goal);
    EXPECT_GT(Clearance(*request.problem.map, other.path), 0.0);
    EXPECT_TRUE(other.metrics.collision_free);
    EXPECT_GE(other.fitness, result->fitness);
    const double mine = CrossingX(result->raw_path, 15.5), theirs = CrossingX(other.path, 15.5);
    EXPECT_TRUE((mine >= 30 && mine <= 34 && theirs >= 4 && theirs <= 8)) << mine << " " << theirs;
  }
  // Without the request there are none; the count is bounded.
  absl::StatusOr<PlanResult> plain = Plan("aem-bso", TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5}, 10);
  ASSERT_TRUE(plain.ok());
  EXPECT_TRUE(plain->alternatives.empty());
  PlanRequest too_many = TwoDoorRequest("aem-bso", 10);
  too_many.problem.alternatives = kMaxAlternatives + 1;
  EXPECT_EQ(ValidatePlanRequest(DefaultRegistry(), too_many).code(),
            absl::StatusCode::kInvalidArgument);
}

TEST(SeededPlannersTest, SameSeedSamePath) {
  for (const std::string& algorithm : kSeededPlanners) {
    SCOPED_TRACE(algorithm);
    absl::StatusOr<PlanResult> a = Plan(algorithm, TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5}, 20);
    absl::StatusOr<PlanResult> b = Plan(algorithm, TwoDoorGrid(), {20.5, 5.5}, {20.5, 25.5}, 20);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->raw_path, b->raw_path);
    EXPECT_EQ(a->fitness, b->fitness);
  }
}

TEST(SeededPlannersTest, PaperInitialisationStillRunsThePapersSearch) {
  for (const std::string& algorithm : kSeededPlanners) {
    SCOPED_TRACE(algorithm);
    absl::StatusOr<PlanResult> paper =
        Plan(algorithm, BlockWorld(), {5, 15}, {35, 15}, 50, {{"init", std::string("paper")}});
    ASSERT_TRUE(paper.ok()) << paper.status();
    EXPECT_EQ(paper->iterations, 50);
    // The paper's decision vector is k = 3 waypoints over the whole map.
    if (paper->found) {
      EXPECT_GT(Clearance(*BlockWorld(), paper->raw_path), 0.0);
    }
  }
}

}  // namespace
}  // namespace swarmplan
