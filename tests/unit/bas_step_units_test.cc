// The BAS family's step_units parameter with init=paper: "cells" keeps the paper's step0 in
// cells, "map" makes the initial step step_fraction of each coordinate's range (the terrain's
// extent in Y between the first and last row's centre, its height range in Z up to the ceiling).

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "beetle_test_support.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::swarmplan::beetle_testing::ExpectSamePath;
using ::swarmplan::beetle_testing::ExpectValidPath;
using ::swarmplan::beetle_testing::RecordingObserver;
using ::swarmplan::beetle_testing::SolveOrDie;

// 24 columns x 17 rows of unit cells, the first centre at the origin (lower-left corner at
// (-0.5, -0.5)): Y runs over 0..16 (range
// 16), the ground is 0 away from a cone 6 high in the middle and the ceiling is 16, so Z also
// ranges over 16. Both ranges are a power of two, so a step of fraction f of the map is exactly
// a step of 16 f cells in floating point.
Problem ConeProblem() {
  constexpr int kWidth = 24, kDepth = 17;
  std::vector<double> heights(kWidth * kDepth);
  for (int y = 0; y < kDepth; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const double distance = std::hypot(x - 12.0, y - 8.0);
      heights[y * kWidth + x] = std::max(0.0, 6.0 - distance);
    }
  }
  Problem problem;
  problem.map = std::make_shared<Map>(
      *Terrain::Create(kWidth, kDepth, heights, 1.0, Point2(-0.5, -0.5), /*ceiling=*/16.0));
  problem.start = Point3(0, 8, 2);
  problem.goal = Point3(kWidth - 1, 8, 2);
  problem.clearance = 0.5;
  problem.seed = 3;
  return problem;
}

ParamValues PaperParams(const std::string& algorithm) {
  ParamValues params = {
      {"iterations", int64_t{150}}, {"init", std::string("paper")}, {"reject_infeasible", false}};
  if (algorithm == "sio-bas" || algorithm == "multi-bas") params["population"] = int64_t{3};
  return params;
}

ParamValues MapSteps(ParamValues params, double fraction, double step0) {
  params["step_units"] = std::string("map");
  params["step_fraction"] = fraction;
  params["step0"] = step0;
  return params;
}

ParamValues CellSteps(ParamValues params, double step0) {
  params["step_units"] = std::string("cells");
  params["step0"] = step0;
  return params;
}

class StepUnitsTest : public ::testing::TestWithParam<std::string> {};

// Fraction 0.25 of ranges of 16 is 4 cells: the same moves, so the same path to the bit.
TEST_P(StepUnitsTest, MapStepIsTheFractionOfTheRange) {
  const Problem problem = ConeProblem();
  RecordingObserver a, b;
  const SearchResult map =
      SolveOrDie(GetParam(), MapSteps(PaperParams(GetParam()), 0.25, 8.0), problem, a);
  const SearchResult cells =
      SolveOrDie(GetParam(), CellSteps(PaperParams(GetParam()), 4.0), problem, b);
  ExpectSamePath(map, cells);
  // A smaller fraction (half a cell) moves differently.
  RecordingObserver c;
  const SearchResult small =
      SolveOrDie(GetParam(), MapSteps(PaperParams(GetParam()), 1.0 / 32, 8.0), problem, c);
  EXPECT_NE(small.fitness, map.fitness);
}

// step_units=map ignores step0; cells (the default) ignores step_fraction.
TEST_P(StepUnitsTest, EachUnitReadsOnlyItsOwnStep) {
  const Problem problem = ConeProblem();
  RecordingObserver a, b, c, d, e;
  ExpectSamePath(SolveOrDie(GetParam(), MapSteps(PaperParams(GetParam()), 0.1, 8.0), problem, a),
                 SolveOrDie(GetParam(), MapSteps(PaperParams(GetParam()), 0.1, 1.0), problem, b));
  ParamValues other_fraction = PaperParams(GetParam());
  other_fraction["step_fraction"] = 0.2;
  ExpectSamePath(SolveOrDie(GetParam(), PaperParams(GetParam()), problem, c),
                 SolveOrDie(GetParam(), other_fraction, problem, d));
  ExpectSamePath(SolveOrDie(GetParam(), PaperParams(GetParam()), problem, c),
                 SolveOrDie(GetParam(), CellSteps(PaperParams(GetParam()), 8.0), problem, e));
}

// A small map-scaled step moves the beetle to better paths than its first one.
TEST_P(StepUnitsTest, SmallMapStepImprovesOnTheFirstPath) {
  const Problem problem = ConeProblem();
  ParamValues params = MapSteps(PaperParams(GetParam()), 1.0 / 32, 8.0);
  params["reject_infeasible"] = true;
  RecordingObserver observer;
  const SearchResult result = SolveOrDie(GetParam(), params, problem, observer);
  ExpectValidPath(result, problem);
  EXPECT_GT(result.best_iteration, 0);
  ASSERT_FALSE(result.convergence.empty());
  EXPECT_LT(result.fitness, result.convergence.front().best_fitness);
}

INSTANTIATE_TEST_SUITE_P(Planners, StepUnitsTest,
                         ::testing::Values("bas", "lfs-bas", "aco-bas", "sio-bas", "multi-bas"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace swarmplan
