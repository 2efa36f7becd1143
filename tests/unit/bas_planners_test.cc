// The beetle antennae family (bas, lfs-bas, aco-bas, sio-bas, multi-bas) and the terrain aco.
// TerrainPlannerTest runs the paper's planners (init=paper, every move taken); SeededTerrainTest
// the service defaults (init=seeded from the terrain-lattice optimum) on a DEM-like terrain.
// On terrain the exact continuous optimum of the paper's fitness is not available (terrain-lattice
// bounds it from above only; see terrain_lattice_test.cc): the paths must beat a feasible fly-over
// reference and stay within a stated factor of the straight distance (ACO moves at most 2 cells
// per column in Y and Z, so its paths zig-zag: factor 2).

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "beetle_test_support.h"
#include "core/algorithms/exact/terrain_lattice.h"
#include "core/geometry/terrain_collision.h"
#include "core/operators/terrain_path_cost.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::swarmplan::beetle_testing::ExpectSamePath;
using ::swarmplan::beetle_testing::ExpectValidPath;
using ::swarmplan::beetle_testing::ExpectWellFormedLog;
using ::swarmplan::beetle_testing::Length;
using ::swarmplan::beetle_testing::RecordingObserver;
using ::swarmplan::beetle_testing::SolveOrDie;

// A 30 x 20 terrain of unit cells with the lower-left corner at the origin (cell centres at
// i + 1/2): ground at 1 with a round hill 8 high in the middle, ceiling 20. Start and goal on
// the first and last column at height 3. `scale` multiplies every length: cell size, origin,
// heights, ceiling, clearance, start and goal.
Problem HillProblem(double scale = 1.0) {
  std::vector<double> heights(30 * 20);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 30; ++x) {
      heights[y * 30 + x] =
          scale *
          (1.0 + 8.0 * std::exp(-((x - 15.0) * (x - 15.0) + (y - 10.0) * (y - 10.0)) / 18.0));
    }
  }
  Problem problem;
  problem.map = std::make_shared<Map>(
      *Terrain::Create(30, 20, heights, scale, Point2(0, 0) * scale, 20.0 * scale));
  problem.start = Point3(0.5, 10.5, 3) * scale;
  problem.goal = Point3(29.5, 10.5, 3) * scale;
  problem.clearance = 0.5 * scale;
  problem.seed = 5;
  return problem;
}

// Fitness of eq 3 for the path flying straight over the hill at height 10 (ground + clearance
// at the top is 9.5): a feasible reference every planner must beat.
double FlyOverFitness() {
  double f = 0.0;
  Point3 prev(0.5, 10.5, 3);
  for (int x = 1; x <= 29; ++x) {
    const Point3 p(x + 0.5, 10.5, x == 29 ? 3.0 : 10.0);
    f += (p - prev).norm() + p.z();
    prev = p;
  }
  return f;
}

struct Case {
  std::string id;
  int64_t iterations;
  int64_t population;  // 0: not a parameter of this planner
  double factor;       // stated bound: length <= factor x the straight start-goal distance
};

class TerrainPlannerTest : public ::testing::TestWithParam<Case> {
 protected:
  ParamValues Params() const {
    ParamValues params = {{"iterations", GetParam().iterations}};
    if (GetParam().id != "aco") {
      params["init"] = std::string("paper");
      params["reject_infeasible"] = false;
    }
    if (GetParam().population > 0) params["population"] = GetParam().population;
    return params;
  }
};

TEST_P(TerrainPlannerTest, FindsALowCollisionFreePath) {
  const Problem problem = HillProblem();
  RecordingObserver observer;
  const SearchResult result = SolveOrDie(GetParam().id, Params(), problem, observer);
  ExpectValidPath(result, problem);
  ExpectWellFormedLog(result, observer);
  EXPECT_EQ(result.path.size(), 30u);  // one waypoint per column
  for (size_t i = 0; i < result.path.size(); ++i) EXPECT_EQ(result.path[i].x(), i + 0.5);
  EXPECT_LT(result.fitness, FlyOverFitness());
  EXPECT_LE(Length(result.path), GetParam().factor * (problem.goal - problem.start).norm());
}

TEST_P(TerrainPlannerTest, SameSeedGivesTheSamePath) {
  const Problem problem = HillProblem();
  RecordingObserver a, b;
  const SearchResult first = SolveOrDie(GetParam().id, Params(), problem, a);
  const SearchResult second = SolveOrDie(GetParam().id, Params(), problem, b);
  ExpectSamePath(first, second);
}

// World units: on the same terrain with every length doubled (cell size 2), the planner runs the
// same search with its cell-given steps doubled, so the path is the same path doubled, to the
// bit (a power of two scales every operation exactly).
TEST_P(TerrainPlannerTest, ScalingTheTerrainScalesThePath) {
  RecordingObserver a, b;
  const SearchResult unit = SolveOrDie(GetParam().id, Params(), HillProblem(1.0), a);
  const SearchResult doubled = SolveOrDie(GetParam().id, Params(), HillProblem(2.0), b);
  ASSERT_TRUE(unit.found);
  ASSERT_TRUE(doubled.found);
  ASSERT_EQ(unit.path.size(), doubled.path.size());
  for (size_t i = 0; i < unit.path.size(); ++i) {
    EXPECT_EQ(doubled.path[i], 2.0 * unit.path[i]) << "point " << i;
  }
  EXPECT_EQ(doubled.fitness, 2.0 * unit.fitness);
}

TEST_P(TerrainPlannerTest, CancelFromTheObserverStopsWithinOneIteration) {
  const Problem problem = HillProblem();
  StopToken stop;
  RecordingObserver observer(stop, 3);
  const SearchResult result = SolveOrDie(GetParam().id, Params(), problem, observer, stop);
  EXPECT_EQ(result.iterations, 4);
  EXPECT_EQ(result.stop_reason, StopReason::kCancelled);
  ExpectWellFormedLog(result, observer);
}

std::string CaseName(const ::testing::TestParamInfo<Case>& info) {
  std::string name = info.param.id;
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Planners, TerrainPlannerTest,
                         ::testing::Values(Case{"bas", 300, 0, 1.6}, Case{"lfs-bas", 300, 0, 1.6},
                                           Case{"aco-bas", 300, 0, 2.0},
                                           Case{"sio-bas", 100, 5, 1.6},
                                           Case{"multi-bas", 100, 5, 1.6}, Case{"aco", 30, 0, 2.0}),
                         CaseName);

// A DEM-like terrain: 48 x 32 cells of 10 m at UTM-like coordinates, ground 480-720 m with two
// ridges across the straight line, a valley bending around them and small-scale roughness, so
// the lattice optimum (levels one cell size, 10 m, apart) flies up to 10 m higher than a
// continuous path must. The query of the bench: the middle row, first to last column, 1 above
// ground + clearance 1.
Problem DemProblem() {
  constexpr int kWidth = 48, kDepth = 32;
  constexpr double kCell = 10.0;
  const Point2 origin(556000.0, 5394000.0);
  std::vector<double> heights(kWidth * kDepth);
  for (int j = 0; j < kDepth; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      const double ridge1 = 140.0 * std::exp(-(i - 15.0) * (i - 15.0) / 10.0) *
                            (1.0 - std::exp(-(j - 6.0) * (j - 6.0) / 20.0));
      const double ridge2 = 120.0 * std::exp(-(i - 32.0) * (i - 32.0) / 12.0) *
                            (1.0 - std::exp(-(j - 25.0) * (j - 25.0) / 20.0));
      heights[j * kWidth + i] =
          500.0 + 2.0 * i + ridge1 + ridge2 + 9.0 * std::sin(1.3 * i) * std::cos(0.9 * j);
    }
  }
  absl::StatusOr<Terrain> terrain = Terrain::Create(kWidth, kDepth, heights, kCell, origin, 900.0);
  Problem problem;
  problem.map = std::make_shared<Map>(*std::move(terrain));
  const Terrain& t = *problem.map->terrain();
  problem.clearance = 1.0;
  const Point2 s = t.CellCentre(0, kDepth / 2), g = t.CellCentre(kWidth - 1, kDepth / 2);
  problem.start = Point3(s.x(), s.y(), t.GroundAt(s) + 2.0);
  problem.goal = Point3(g.x(), g.y(), t.GroundAt(g) + 2.0);
  problem.seed = 7;
  return problem;
}

double LatticeOptimum(const Problem& problem) {
  absl::StatusOr<TerrainLatticeResult> lattice =
      TerrainLatticeOptimum(*problem.map->terrain(), problem.start, problem.goal, problem.clearance,
                            TerrainLatticeOptions());
  EXPECT_TRUE(lattice.ok()) << lattice.status();
  if (!lattice.ok() || lattice->path.empty()) return 0.0;
  return lattice->cost;
}

class SeededTerrainTest : public ::testing::TestWithParam<std::string> {};

// The service defaults: seeded from the lattice optimum, the result joins start and goal, is
// collision-free by the terrain's checker, costs no more than the seed (<= 1.05 x the lattice
// optimum) and improves on it: the best is found after iteration 0.
TEST_P(SeededTerrainTest, ImprovesOnTheLatticeSeed) {
  const Problem problem = DemProblem();
  const double optimum = LatticeOptimum(problem);
  ASSERT_GT(optimum, 0.0);
  RecordingObserver observer;
  const SearchResult result = SolveOrDie(GetParam(), {}, problem, observer);
  ExpectValidPath(result, problem);
  ExpectWellFormedLog(result, observer);
  EXPECT_EQ(result.path.front(), problem.start);
  EXPECT_EQ(result.path.back(), problem.goal);
  EXPECT_TRUE(
      TerrainCollisionChecker(*problem.map->terrain()).PathFree(result.path, problem.clearance));
  const double cost = TerrainPathCost(result.path, problem.map->terrain()->cell_size());
  EXPECT_LE(cost, optimum);
  EXPECT_LE(cost, 1.05 * optimum);
  EXPECT_LT(cost, optimum - 1.0);  // better than the seed by more than rounding
  EXPECT_GT(result.best_iteration, 0);
}

TEST_P(SeededTerrainTest, SameSeedGivesTheSamePath) {
  const Problem problem = DemProblem();
  RecordingObserver a, b;
  const SearchResult first = SolveOrDie(GetParam(), {}, problem, a);
  const SearchResult second = SolveOrDie(GetParam(), {}, problem, b);
  ExpectSamePath(first, second);
}

INSTANTIATE_TEST_SUITE_P(Planners, SeededTerrainTest,
                         ::testing::Values("bas", "lfs-bas", "aco-bas", "sio-bas", "multi-bas"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

// The paper's distinction (SIO-BAS vs Multi-BAS, eqs 16-18): the same population from the same
// seed, the only difference the direction's pull toward the swarm's best and the previous
// better-antenna side. Where moving matters (a seed with height to lose), the paths differ.
TEST(SeededTerrainTest, SioBasDiffersFromMultiBas) {
  const Problem problem = DemProblem();
  RecordingObserver a, b;
  const SearchResult sio = SolveOrDie("sio-bas", {}, problem, a);
  const SearchResult multi = SolveOrDie("multi-bas", {}, problem, b);
  ASSERT_TRUE(sio.found);
  ASSERT_TRUE(multi.found);
  EXPECT_GT(sio.best_iteration, 0);
  EXPECT_GT(multi.best_iteration, 0);
  EXPECT_NE(sio.fitness, multi.fitness);
  bool differ = sio.path.size() != multi.path.size();
  for (size_t i = 0; !differ && i < sio.path.size(); ++i) differ = sio.path[i] != multi.path[i];
  EXPECT_TRUE(differ);
  // With eta2 = eta3 = 0 sio-bas is multi-bas: the same path to the bit.
  RecordingObserver c;
  const SearchResult sio_plain =
      SolveOrDie("sio-bas", {{"eta1", 1.0}, {"eta2", 0.0}, {"eta3", 0.0}}, problem, c);
  ExpectSamePath(sio_plain, multi);
}

// init=paper keeps the paper's search: no seed, so nothing ties it to the lattice path.
TEST(SeededTerrainTest, PaperInitIsStillAvailable) {
  const Problem problem = DemProblem();
  RecordingObserver observer;
  const SearchResult result = SolveOrDie(
      "bas", {{"init", std::string("paper")}, {"reject_infeasible", false}}, problem, observer);
  EXPECT_GT(result.iterations, 0);
  if (result.found) ExpectValidPath(result, problem);
}

TEST(TerrainPlannerTest, RejectsStartAndGoalInTheSameColumn) {
  Problem problem = HillProblem();
  problem.goal = {1.5, 5.5, 3};
  absl::StatusOr<std::unique_ptr<Planner>> planner =
      beetle_testing::BeetleRegistry().Create("bas", {});
  ASSERT_TRUE(planner.ok());
  NullObserver observer;
  EXPECT_FALSE((*planner)->Solve(problem, StopToken(), observer).ok());
}

// The same planner ids on a 2D map: k = 2 waypoints and a spline.
Problem CirclesProblem() {
  Problem problem;
  problem.map = std::make_shared<Map>(*ShapeWorld::Create(
      {{0, 0}, {40, 40}}, {{{20, 20}, 4.0}, {{10, 30}, 2.0}, {{30, 10}, 2.0}}, {}));
  problem.start = {2, 2, 0};
  problem.goal = {38, 38, 0};
  problem.seed = 3;
  return problem;
}

TEST(BasOn2dMapsTest, FindsShortPaths) {
  const Problem problem = CirclesProblem();
  // The exact optimum around the middle circle (see bso_planners_test.cc).
  const double d = 18.0 * std::sqrt(2.0), r = 4.0;
  const double optimum =
      2.0 * std::sqrt(d * d - r * r) + r * (std::numbers::pi - 2.0 * std::acos(r / d));
  const std::vector<std::pair<std::string, ParamValues>> runs = {
      {"bas", {{"iterations", int64_t{300}}}},
      {"lfs-bas", {{"iterations", int64_t{300}}}},
      {"bas", {{"iterations", int64_t{300}}, {"pso_mix", true}}},
      {"sio-bas", {{"iterations", int64_t{150}}}},
      {"multi-bas", {{"iterations", int64_t{150}}}},
  };
  for (const auto& [id, params] : runs) {
    SCOPED_TRACE(id);
    RecordingObserver observer;
    const SearchResult result = SolveOrDie(id, params, problem, observer);
    ExpectValidPath(result, problem);
    ExpectWellFormedLog(result, observer);
    EXPECT_LE(Length(result.path), 1.25 * optimum);  // stated bound
  }
}

}  // namespace
}  // namespace swarmplan
