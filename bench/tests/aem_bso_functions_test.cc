#include <cmath>
#include <limits>
#include <numbers>

#include "bench/papers/aem_bso_functions_convergence.h"
#include "bench/papers/aem_bso_functions_runs.h"
#include "bench/papers/aem_bso_test_functions.h"
#include "bench/papers/experiment.h"
#include "core/algorithms/bso/swarm_options.h"
#include "core/planner.h"
#include "core/random.h"
#include "core/registry.h"
#include "core/stop_token.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

using std::numbers::pi;

Eigen::VectorXd Vec(std::initializer_list<double> values) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double v : values) x[i++] = v;
  return x;
}

const TestFunction& Function(const std::string& id) {
  for (const TestFunction& function : AemBsoTestFunctions()) {
    if (function.id == id) return function;
  }
  ADD_FAILURE() << "no " << id;
  return AemBsoTestFunctions().front();
}

TEST(AemBsoTestFunctionsTest, TenFunctionsWithThePapersRanges) {
  const std::vector<TestFunction>& functions = AemBsoTestFunctions();
  ASSERT_EQ(functions.size(), 10u);
  const double ranges[10] = {100, 100, 50, 100, 10, 100, 5.2, 600, 32, 50};
  for (size_t i = 0; i < functions.size(); ++i) {
    EXPECT_EQ(functions[i].id, "f" + std::to_string(i + 1));
    EXPECT_EQ(functions[i].upper, ranges[i]) << functions[i].id;
    EXPECT_EQ(functions[i].lower, -ranges[i]) << functions[i].id;
    EXPECT_EQ(functions[i].unimodal, i < 6) << functions[i].id;
  }
}

TEST(AemBsoTestFunctionsTest, KnownMinimiserGivesKnownMinimum) {
  for (const TestFunction& function : AemBsoTestFunctions()) {
    for (int dim : {2, 30, 60}) {
      EXPECT_NEAR(function.value(function.Minimiser(dim)), function.minimum, 1e-12)
          << function.id << " D = " << dim;
    }
  }
}

TEST(AemBsoTestFunctionsTest, NoPointBelowTheKnownMinimum) {
  Rng rng(7);
  for (const TestFunction& function : AemBsoTestFunctions()) {
    for (int k = 0; k < 200; ++k) {
      Eigen::VectorXd x(30);
      for (double& xi : x) xi = rng.Uniform(function.lower, function.upper) * rng.Uniform();
      EXPECT_GE(function.value(x), function.minimum - 1e-9) << function.id;
    }
  }
}

TEST(AemBsoTestFunctionsTest, HandComputedPoints) {
  EXPECT_DOUBLE_EQ(Sphere(Vec({1, 2, 3})), 14.0);
  // floor(0.9) = 0, floor(-0.1) = -1, floor(2.0) = 2.
  EXPECT_DOUBLE_EQ(Step(Vec({0.4, -0.6, 1.5})), 5.0);
  EXPECT_DOUBLE_EQ(Rosenbrock(Vec({0, 0, 0})), 2.0);
  EXPECT_DOUBLE_EQ(Rosenbrock(Vec({1, 2})), 100.0);
  // Prefix sums of squares 1, 5, 14.
  EXPECT_DOUBLE_EQ(Quadric(Vec({1, 2, 3})), 20.0);
  EXPECT_DOUBLE_EQ(SchwefelP222(Vec({1, -2, 3})), 6.0 + 6.0);
  // Weights 1, 1e3, 1e6.
  EXPECT_NEAR(Elliptic(Vec({1, 1, 1})), 1001001.0, 1e-6);
  EXPECT_NEAR(Elliptic(Vec({0, 2, 0})), 4000.0, 1e-9);
  // 1 - 10 cos(2 pi) + 10 = 1 and 0.25 - 10 cos(pi) + 10 = 20.25.
  EXPECT_NEAR(Rastrigin(Vec({1, 0.5})), 21.25, 1e-12);
  // cos(pi / 2) = 0 zeroes the product.
  EXPECT_NEAR(Griewank(Vec({pi / 2, 0})), pi * pi / 16000.0 + 1.0, 1e-12);
  // sqrt(mean x^2) = 1 and mean cos(2 pi x) = 1.
  EXPECT_NEAR(Ackley(Vec({1, 1})), 20.0 * (1.0 - std::exp(-0.2)), 1e-12);
  // 1 + 0 - 0.3 cos(3 pi) - 0.4 cos(4 pi) + 0.7.
  EXPECT_NEAR(Bohachevsky(Vec({1, 0})), 1.6, 1e-12);
}

TEST(AemBsoTestFunctionsTest, ObjectiveIsTheFunctionOverItsBox) {
  const TestFunction& rastrigin = Function("f7");
  TestFunctionObjective objective(rastrigin, 3);
  EXPECT_EQ(objective.dim(), 3);
  EXPECT_EQ(objective.lower(), Eigen::VectorXd::Constant(3, -5.2));
  EXPECT_EQ(objective.upper(), Eigen::VectorXd::Constant(3, 5.2));
  const Evaluation e = objective.Evaluate(Vec({1, 0.5, 0}));
  EXPECT_NEAR(e.fitness, 21.25, 1e-12);
  EXPECT_TRUE(e.feasible);
}

TEST(AemBsoTestFunctionsTest, ShiftMovesTheMinimiser) {
  const TestFunction& sphere = Function("f1");
  TestFunctionObjective objective(sphere, 2, Vec({20, -20}));
  EXPECT_DOUBLE_EQ(objective.Evaluate(Vec({20, -20})).fitness, 0.0);
  EXPECT_DOUBLE_EQ(objective.Evaluate(Vec({0, 0})).fitness, 800.0);
}

TEST(AemBsoTestFunctionsTest, CheckOptimiserResultAcceptsOnlyRealResults) {
  const TestFunction& sphere = Function("f1");
  TestFunctionObjective objective(sphere, 2);
  EXPECT_TRUE(CheckOptimiserResult(sphere, objective, Vec({1, 2}), 5.0).ok());
  EXPECT_TRUE(CheckOptimiserResult(sphere, objective, Vec({0, 0}), 0.0).ok());
  EXPECT_FALSE(CheckOptimiserResult(sphere, objective, Vec({1, 2}), 4.0).ok());
  EXPECT_FALSE(CheckOptimiserResult(sphere, objective, Vec({0, 0}), -1e-6).ok());
  EXPECT_FALSE(
      CheckOptimiserResult(sphere, objective, Vec({0, 0}), std::numeric_limits<double>::quiet_NaN())
          .ok());
  EXPECT_FALSE(CheckOptimiserResult(sphere, objective, Vec({101, 0}), 10201.0).ok());
  const TestFunction& ackley = Function("f9");
  TestFunctionObjective ackley_objective(ackley, 2);
  // Rounding may leave Ackley a few ulps below 0 at the origin (the paper reports -4.44e-16).
  EXPECT_TRUE(
      CheckOptimiserResult(ackley, ackley_objective, Vec({0, 0}), ackley.value(Vec({0, 0}))).ok());
}

// The experiment runs the planners' own optimisers; each must improve on the sphere.
TEST(AemBsoSwarmOptimiserTest, EveryPlannerOptimiserMinimisesTheSphere) {
  const TestFunction& sphere = Function("f1");
  for (const char* id : {"aem-bso", "aem-bso-linear", "bso", "pso", "ba"}) {
    const PlannerInfo* info = DefaultRegistry().Find(id);
    ASSERT_NE(info, nullptr) << id;
    absl::StatusOr<ParamSet> params =
        ParamSet::Resolve(info->params, ParamValues{{"population", int64_t{20}}});
    ASSERT_TRUE(params.ok()) << params.status();
    absl::StatusOr<SwarmOptimiser> optimiser = SwarmOptimiserFor(id, *params);
    ASSERT_TRUE(optimiser.ok()) << optimiser.status();
    TestFunctionObjective objective(sphere, 5);
    Rng rng(3);
    NullObserver observer;
    const SearchOutcome outcome = (*optimiser)(objective, 50, rng, StopToken(), observer);
    EXPECT_EQ(outcome.iterations, 50) << id;
    EXPECT_TRUE(CheckOptimiserResult(sphere, objective, outcome.best_x, outcome.best_fitness).ok())
        << id;
    // A random point of the box has expected value 5 * 100^2 / 3 ~ 16667.
    EXPECT_LT(outcome.best_fitness, 2000.0) << id;
  }
  EXPECT_FALSE(SwarmOptimiserFor("astar", ParamSet()).ok());
}

TEST(AemBsoConvergenceTest, CheckpointsAreFractionsOfTheRunWithoutRepeats) {
  EXPECT_EQ(aem_bso::ConvergenceCheckpoints(1000), std::vector<int>({10, 50, 100, 250, 500, 1000}));
  EXPECT_EQ(aem_bso::ConvergenceCheckpoints(20), std::vector<int>({1, 2, 5, 10, 20}));
  EXPECT_EQ(aem_bso::ConvergenceCheckpoints(1), std::vector<int>({1}));
}

// Each run keeps its best so far at the checkpoints: non-increasing, ending at its final best.
TEST(AemBsoConvergenceTest, RunsKeepTheirBestSoFarAtTheCheckpoints) {
  aem_bso::FunctionJob job{{"AEM-BSO", "aem-bso", {}, 1}, &Function("f9"), 5, false, 3};
  ExperimentOptions options;
  absl::StatusOr<std::vector<aem_bso::FunctionCell>> cells =
      aem_bso::RunFunctionJobs({job}, 40, 10, 1, options);
  ASSERT_TRUE(cells.ok()) << cells.status();
  const aem_bso::FunctionCell& cell = cells->front();
  ASSERT_EQ(cell.best_so_far.size(), aem_bso::ConvergenceCheckpoints(40).size());
  for (int r = 0; r < 3; ++r) {
    for (size_t k = 0; k < cell.best_so_far.size(); ++k) {
      ASSERT_EQ(cell.best_so_far[k].size(), 3u);
      if (k > 0) {
        EXPECT_LE(cell.best_so_far[k][r], cell.best_so_far[k - 1][r]);
      }
    }
    EXPECT_EQ(cell.best_so_far.back()[r], cell.best_values[r]);
  }
}

// The section marks where column 0 is significantly below or above another column.
TEST(AemBsoConvergenceTest, SectionMarksSignificantCheckpoints) {
  const std::vector<int> checkpoints = aem_bso::ConvergenceCheckpoints(20);
  aem_bso::FunctionCell low, high, mixed;
  for (size_t k = 0; k < checkpoints.size(); ++k) {
    std::vector<double> small, large;
    for (int r = 0; r < 10; ++r) {
      small.push_back(1.0 + 0.01 * r);
      large.push_back(5.0 + 0.01 * r);
    }
    low.best_so_far.push_back(small);
    high.best_so_far.push_back(large);
    // Above column 0 early, below it from checkpoint 2 on.
    mixed.best_so_far.push_back(k < 2 ? large : std::vector<double>(10, 0.5));
  }
  const aem_bso::CellGrid cells = {{low, high, mixed}};
  std::string summary;
  const std::string section =
      aem_bso::ConvergenceSection({&Function("f1")}, {"A", "B", "C"}, cells, 1, 30, 20, &summary);
  EXPECT_NE(section.find("| f1 | B |"), std::string::npos) << section;
  EXPECT_NE(section.find("| all | – |"), std::string::npos) << section;
  EXPECT_NE(section.find("| 1, 2 | 5, 10, 20 |"), std::string::npos) << section;
  EXPECT_EQ(summary,
            "A is significantly below B, C at every checkpoint on 0 of 1 functions (none) and "
            "at the last one on 0 (none); below all 2 others at every checkpoint on 0 (none); "
            "another optimiser is significantly below A at some checkpoint on 1 (f1 (C))");
}

}  // namespace
}  // namespace swarmplan::bench
