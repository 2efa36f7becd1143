#include <gtest/gtest.h>

#include <string>

#include "core/fitness/path_objective_terms.h"
#include "core/registry.h"
#include "core/run.h"
#include "tests/unit/seed_test_maps.h"

namespace swarmplan {
namespace {

PlanRequest FleetRequest(const std::string& algorithm, uint64_t seed) {
  PlanRequest request;
  request.algorithm = algorithm;
  request.problem.map = seed_testing::TwoDoorGrid();
  request.problem.start = {35.5, 3.5, 0};
  request.problem.goal = {2.5, 27.5, 0};
  request.problem.clearance = 0.5;
  request.problem.fleet.preferred_clearance = 1.5;
  request.problem.fleet.turning_radius = 2.0;
  request.problem.limits.max_iterations = 2;
  request.problem.seed = seed;
  request.smoothing = "bounded-curvature";
  return request;
}

TEST(PlanObjectiveTest, ASeededPlanIsNeverWorseThanItsSmoothedSeed) {
  for (const std::string algorithm : {"aem-bso", "pso", "ba"}) {
    for (uint64_t seed = 1; seed <= 6; ++seed) {
      SCOPED_TRACE(algorithm + " seed " + std::to_string(seed));
      const PlanRequest request = FleetRequest(algorithm, seed);
      NullObserver observer;
      absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, {}, observer);
      ASSERT_TRUE(result.ok()) << result.status();
      ASSERT_TRUE(result->found);
      ASSERT_TRUE(result->objective.has_value());
      ASSERT_TRUE(result->seed_objective.has_value());
      EXPECT_LE(result->objective->Total(), result->seed_objective->Total());
      // The reported terms are those of the returned path.
      const absl::StatusOr<FleetTerms> again =
          EvaluateFleetObjective(request.problem, result->smoothed_path);
      ASSERT_TRUE(again.ok());
      EXPECT_DOUBLE_EQ(again->Total(), result->objective->Total());
      EXPECT_TRUE(result->smoothing_collision_free);
      EXPECT_GE(seed_testing::Clearance(*request.problem.map, result->smoothed_path), 0.5 - 1e-9);
    }
  }
}

TEST(PlanObjectiveTest, PlansWithoutSeedsReportOnlyTheirOwnObjective) {
  PlanRequest request = FleetRequest("exact-any-angle", 1);
  NullObserver observer;
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, {}, observer);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_TRUE(result->objective.has_value());
  EXPECT_FALSE(result->seed_objective.has_value());
  EXPECT_GE(result->objective->length, result->smoothed_metrics.length - 1e-9);
  EXPECT_GT(result->objective->clearance, 0.0);  // the exact path grazes the door's wall
}

}  // namespace
}  // namespace swarmplan
