// The 2D waypoint swarm planners: bso, aem-bso, aem-bso-linear, pso, ba.

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "beetle_test_support.h"
#include "core/optimum.h"
#include "core/registry.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::swarmplan::beetle_testing::ExpectSamePath;
using ::swarmplan::beetle_testing::ExpectValidPath;
using ::swarmplan::beetle_testing::ExpectWellFormedLog;
using ::swarmplan::beetle_testing::Length;
using ::swarmplan::beetle_testing::RecordingObserver;
using ::swarmplan::beetle_testing::SolveOrDie;

// A 40 x 40 world with three circles; the straight start-goal line crosses the big one.
Problem CirclesProblem() {
  Problem problem;
  problem.map = std::make_shared<Map>(*ShapeWorld::Create(
      {{0, 0}, {40, 40}}, {{{20, 20}, 4.0}, {{10, 30}, 2.0}, {{30, 10}, 2.0}}, {}));
  problem.start = {2, 2, 0};
  problem.goal = {38, 38, 0};
  problem.seed = 42;
  return problem;
}

// A 40 x 40 grid with a wall at x = 16..17 from y = 0 to 24 and a block at x 28..31,
// y 6..9.
Problem GridProblem() {
  std::vector<int8_t> cells(40 * 40, 0);
  for (int y = 0; y <= 24; ++y) cells[y * 40 + 16] = cells[y * 40 + 17] = 100;
  for (int y = 6; y <= 9; ++y) {
    for (int x = 28; x <= 31; ++x) cells[y * 40 + x] = 100;
  }
  Problem problem;
  problem.map = std::make_shared<Map>(*OccupancyGrid::Create(40, 40, cells));
  problem.start = {4.5, 4.5, 0};
  problem.goal = {36.5, 36.5, 0};
  problem.seed = 7;
  return problem;
}

double ExactOptimum(const Problem& problem) {
  if (problem.map->world() != nullptr) {
    // Around the circle of radius r = 4 whose centre lies on the start-goal diagonal at
    // d = 18 sqrt(2) from both ends: two tangents sqrt(d^2 - r^2) and the arc
    // r (pi - 2 acos(r / d)); the small circles are far from it.
    const double d = 18.0 * std::sqrt(2.0), r = 4.0;
    return 2.0 * std::sqrt(d * d - r * r) + r * (std::numbers::pi - 2.0 * std::acos(r / d));
  }
  const Optimum optimum = ComputeOptimum(DefaultRegistry(), problem, absl::Seconds(10));
  EXPECT_TRUE(optimum.known) << optimum.reason;
  return optimum.length;
}

struct Case {
  std::string id;
  bool grid;
  double factor;  // stated bound: length <= factor x exact optimum
  int64_t population = 30;
};

class SwarmPlannerTest : public ::testing::TestWithParam<Case> {
 protected:
  Problem MakeProblem() const { return GetParam().grid ? GridProblem() : CirclesProblem(); }
  ParamValues SmallParams() const {
    return {{"population", GetParam().population}, {"iterations", int64_t{80}}};
  }
};

TEST_P(SwarmPlannerTest, FindsAShortCollisionFreePath) {
  const Problem problem = MakeProblem();
  RecordingObserver observer;
  const SearchResult result = SolveOrDie(GetParam().id, SmallParams(), problem, observer);
  ExpectValidPath(result, problem);
  ExpectWellFormedLog(result, observer);
  EXPECT_EQ(result.iterations, 80);
  EXPECT_EQ(result.stop_reason, StopReason::kIterationCap);
  const double optimum = ExactOptimum(problem);
  EXPECT_LE(Length(result.path), GetParam().factor * optimum)
      << "optimum " << optimum << " fitness " << result.fitness;
  EXPECT_GE(Length(result.path), optimum - 1e-6);
}

TEST_P(SwarmPlannerTest, SameSeedGivesTheSamePath) {
  const Problem problem = MakeProblem();
  RecordingObserver first_observer, second_observer;
  const ParamValues params = {{"population", int64_t{10}}, {"iterations", int64_t{20}}};
  const SearchResult first = SolveOrDie(GetParam().id, params, problem, first_observer);
  const SearchResult second = SolveOrDie(GetParam().id, params, problem, second_observer);
  ExpectSamePath(first, second);
  EXPECT_EQ(first.evaluations, second.evaluations);
}

TEST_P(SwarmPlannerTest, CancelFromTheObserverStopsWithinOneIteration) {
  const Problem problem = MakeProblem();
  StopToken stop;
  RecordingObserver observer(stop, 3);
  const SearchResult result = SolveOrDie(GetParam().id, SmallParams(), problem, observer, stop);
  EXPECT_EQ(result.iterations, 4);
  EXPECT_EQ(result.stop_reason, StopReason::kCancelled);
  ExpectWellFormedLog(result, observer);
}

TEST_P(SwarmPlannerTest, ProblemIterationCapLowersTheIterations) {
  Problem problem = MakeProblem();
  problem.limits.max_iterations = 5;
  RecordingObserver observer;
  const SearchResult result = SolveOrDie(GetParam().id, SmallParams(), problem, observer);
  EXPECT_EQ(result.iterations, 5);
  EXPECT_EQ(result.stop_reason, StopReason::kIterationCap);
}

std::string CaseName(const ::testing::TestParamInfo<Case>& info) {
  std::string name = info.param.id + (info.param.grid ? "_grid" : "_shapes");
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Planners, SwarmPlannerTest,
                         ::testing::Values(Case{"bso", false, 1.1}, Case{"aem-bso", false, 1.1},
                                           Case{"aem-bso-linear", false, 1.1},
                                           Case{"pso", false, 1.1}, Case{"ba", false, 1.1, 60},
                                           Case{"bso", true, 1.1}, Case{"aem-bso", true, 1.1},
                                           Case{"aem-bso-linear", true, 1.1},
                                           Case{"pso", true, 1.1}, Case{"ba", true, 1.1}),
                         CaseName);

TEST(SwarmPlannerParamsTest, InterpolationsAllPlan) {
  const Problem problem = CirclesProblem();
  for (const std::string interpolation : {"spline", "linear", "nearest"}) {
    RecordingObserver observer;
    const SearchResult result = SolveOrDie("aem-bso",
                                           {{"population", int64_t{30}},
                                            {"iterations", int64_t{60}},
                                            {"interpolation", interpolation}},
                                           problem, observer);
    ExpectValidPath(result, problem);
  }
}

TEST(SwarmPlannerParamsTest, RejectsBadParameters) {
  EXPECT_FALSE(beetle_testing::BeetleRegistry()
                   .Create("aem-bso", {{"interpolation", std::string("cubic")}})
                   .ok());
  EXPECT_FALSE(beetle_testing::BeetleRegistry().Create("bso", {{"population", int64_t{0}}}).ok());
  EXPECT_FALSE(beetle_testing::BeetleRegistry().Create("pso", {{"c3", 1.0}}).ok());
}

TEST(SwarmPlannerParamsTest, PaperDefaults) {
  const PlannerInfo* info = beetle_testing::BeetleRegistry().Find("aem-bso");
  ASSERT_NE(info, nullptr);
  ParamValues defaults;
  for (const ParamSpec& spec : info->params) defaults[spec.name] = spec.default_value;
  EXPECT_EQ(std::get<int64_t>(defaults["population"]), 100);
  EXPECT_EQ(std::get<int64_t>(defaults["iterations"]), 500);
  EXPECT_EQ(std::get<double>(defaults["w_max"]), 0.9);
  EXPECT_EQ(std::get<double>(defaults["w_min"]), 0.4);
  EXPECT_EQ(std::get<double>(defaults["c3"]), 1.49);
  EXPECT_EQ(std::get<double>(defaults["penalty"]), 100.0);
  EXPECT_EQ(std::get<double>(defaults["d_safe"]), 1.5);
  EXPECT_EQ(std::get<std::string>(defaults["inertia"]), "cosine");
}

}  // namespace
}  // namespace swarmplan
