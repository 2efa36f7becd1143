// The fitness engine (core/fitness) against the reference path: WaypointPathBuilder's spline
// and ObstacleProximity's exact count, on every map kind; the distance fields' bounds; the
// fleet objective's terms.
#include "core/fitness/fitness_engine.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/fitness/path_objective_terms.h"
#include "core/fitness/reference_objective.h"
#include "core/geometry/collision.h"
#include "core/geometry/primitives.h"
#include "core/geometry/rasterize.h"
#include "core/map/generate.h"
#include "core/map/io/map_io.h"
#include "core/operators/waypoint_objective.h"
#include "core/operators/waypoint_path.h"
#include "core/random.h"
#include "gtest/gtest.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

// Relative error allowed between the engine's fitness and the reference's: the two build the
// same spline points in a different order of floating-point operations.
constexpr double kRelativeError = 1e-9;

struct MapCase {
  std::string name;
  MapPtr map;
  Point3 start, goal;
};

std::vector<MapCase> MapCases() {
  const Bounds2 bounds{Point2(0, 0), Point2(100, 100)};
  const std::vector<Point2> keep = {Point2(10, 10), Point2(90, 90)};
  std::vector<MapCase> cases;
  const ShapeWorld ten = *RandomShapeWorld(bounds, 10, 5, 10, 1, keep, 3);
  const ShapeWorld thirty = *RandomShapeWorld(bounds, 30, 3, 7, 1, keep, 3);
  RandomWorldOptions mixed;
  mixed.keep_clear = keep;
  mixed.keep_clear_radius = 3;
  cases.push_back({"10 circles", std::make_shared<Map>(ten), {10, 10, 0}, {90, 90, 0}});
  cases.push_back({"30 circles", std::make_shared<Map>(thirty), {10, 10, 0}, {90, 90, 0}});
  cases.push_back({"circles and polygons",
                   std::make_shared<Map>(*RandomShapeWorld(mixed, 3)),
                   {10, 10, 0},
                   {90, 90, 0}});
  cases.push_back({"grid 100x100",
                   std::make_shared<Map>(*RasterizeShapeWorld(thirty, 1.0)),
                   {10.5, 10.5, 0},
                   {89.5, 89.5, 0}});
  cases.push_back({"grid 50x50 at 2",
                   std::make_shared<Map>(*RasterizeShapeWorld(thirty, 2.0)),
                   {11, 11, 0},
                   {89, 89, 0}});
  return cases;
}

// Compares the engine with the reference on `count` decision vectors: around the straight
// line (like a swarm's positions), uniform in the box (paths leaving the map too), and feasible
// vectors found by random search and moved a little (paths grazing the safety distance).
// Returns how many were feasible.
int ExpectSameAsReference(const MapCase& c, const WaypointFitnessOptions& options, int count) {
  Problem problem;
  problem.map = c.map;
  problem.start = c.start;
  problem.goal = c.goal;
  auto objective = WaypointObjective::Create(problem, options);
  EXPECT_TRUE(objective.ok()) << objective.status();
  if (!objective.ok()) return 0;
  auto reference = ReferenceWaypointObjective::Create(problem, options);
  EXPECT_TRUE(reference.ok()) << reference.status();
  if (!reference.ok()) return 0;
  Rng rng(11);
  const int dim = 2 * options.waypoints;
  Eigen::VectorXd x(dim);
  // Feasible vectors by random search.
  std::vector<Eigen::VectorXd> feasible_pool;
  for (int tries = 0; tries < 10 * count && static_cast<int>(feasible_pool.size()) < 50; ++tries) {
    (*objective)->SampleAroundStraightPath(tries % 2 ? 15.0 : 40.0, rng, x);
    if ((*objective)->Evaluate(x).feasible) feasible_pool.push_back(x);
  }
  Eigen::MatrixXd xs(dim, count);
  for (int j = 0; j < count; ++j) {
    if (j % 4 == 1 && !feasible_pool.empty()) {
      x = feasible_pool[j % feasible_pool.size()];
      for (int d = 0; d < dim; ++d) x[d] += rng.Uniform(-1.0, 1.0);
      (*objective)->Clamp(x);
    } else if (j % 4 == 3) {
      for (int d = 0; d < dim; ++d)
        x[d] = rng.Uniform((*objective)->lower()[d], (*objective)->upper()[d]);
    } else {
      (*objective)->SampleAroundStraightPath(j % 4 == 0 ? 5.0 : 30.0, rng, x);
    }
    xs.col(j) = x;
  }
  std::vector<Evaluation> batch(count);
  (*objective)->EvaluateColumns(xs, batch.data());
  int feasible = 0, mismatches = 0;
  for (int j = 0; j < count; ++j) {
    x = xs.col(j);
    const Evaluation expected = (*reference)->Evaluate(x);
    const Evaluation single = (*objective)->Evaluate(x);
    EXPECT_EQ(single.fitness, batch[j].fitness);
    if (expected.feasible != batch[j].feasible ||
        std::abs(expected.fitness - batch[j].fitness) > kRelativeError * expected.fitness) {
      if (++mismatches <= 3) {
        ADD_FAILURE() << c.name << " k=" << options.waypoints << " vector " << j << ": engine "
                      << batch[j].fitness << " (" << batch[j].feasible << "), reference "
                      << expected.fitness << " (" << expected.feasible << ")";
      }
    }
    feasible += expected.feasible ? 1 : 0;
  }
  EXPECT_EQ(mismatches, 0) << c.name;
  EXPECT_LT(feasible, count) << c.name << " k=" << options.waypoints;
  return feasible;
}

TEST(FitnessEngineTest, SplineMatchesTheReferenceOnEveryMapKind) {
  for (const MapCase& c : MapCases()) {
    int feasible = 0;
    for (int k : {2, 3, 5, 8}) {
      WaypointFitnessOptions options;
      options.waypoints = k;
      feasible += ExpectSameAsReference(c, options, 600);
    }
    // Both verdicts occur (xi itself is compared through the fitness L (1 + M xi)).
    EXPECT_GT(feasible, 20) << c.name;
  }
}

TEST(FitnessEngineTest, StraightAndStaircaseMatchTheReference) {
  for (const MapCase& c : MapCases()) {
    for (Interpolation interpolation : {Interpolation::kLinear, Interpolation::kNearest}) {
      WaypointFitnessOptions options;
      options.interpolation = interpolation;
      ExpectSameAsReference(c, options, 500);
    }
  }
}

TEST(FitnessEngineTest, MatchesTheReferenceOnSharedMaps) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/Berlin_0_256.map");
  SWARMPLAN_REQUIRE_BENCHMARKS("polygons/parking1.geojson");
  const std::string dir = testing::BenchmarksDir();
  absl::StatusOr<Map> berlin = LoadMapFile(dir + "/movingai/Berlin_0_256.map");
  ASSERT_TRUE(berlin.ok()) << berlin.status();
  absl::StatusOr<Map> parking = LoadMapFile(dir + "/polygons/parking1.geojson");
  ASSERT_TRUE(parking.ok()) << parking.status();
  std::vector<MapCase> cases;
  cases.push_back({"Berlin_0_256", std::make_shared<Map>(*std::move(berlin)), {}, {}});
  cases.push_back({"parking1", std::make_shared<Map>(*std::move(parking)), {}, {}});
  for (MapCase& c : cases) {
    // Start and goal near opposite corners of the map's rectangle.
    const ObstacleProximity proximity = *ObstacleProximity::Create(*c.map, 1.5);
    const Point2 lo = proximity.lower(), hi = proximity.upper();
    const Point2 a = lo + 0.1 * (hi - lo), b = lo + 0.9 * (hi - lo);
    c.start = Point3(a.x(), a.y(), 0);
    c.goal = Point3(b.x(), b.y(), 0);
    WaypointFitnessOptions options;
    ExpectSameAsReference(c, options, 1000);
  }
}

TEST(InterpolationBasisTest, IsCachedAndReproducesTheBuilder) {
  auto first = CachedInterpolationBasis(Interpolation::kSpline, 3, 100);
  auto second = CachedInterpolationBasis(Interpolation::kSpline, 3, 100);
  EXPECT_EQ(first.get(), second.get());
  EXPECT_EQ(first->points(), 100);
  EXPECT_EQ(first->knots(), 5);
  EXPECT_EQ(InterpolationBasis(Interpolation::kNearest, 1, 100).points(), 7);
  // Every interpolation at several waypoint counts against WaypointPathBuilder on random knots.
  Rng rng(5);
  for (const Interpolation interpolation : {Interpolation::kSpline, Interpolation::kLinear,
                                            Interpolation::kPolyline, Interpolation::kNearest}) {
    for (const int k : {1, 2, 3, 5, 8, 64}) {
      const InterpolationBasis basis(interpolation, k, 257);
      const Point3 start(rng.Uniform(0, 100), rng.Uniform(0, 100), 0);
      const Point3 goal(rng.Uniform(0, 100), rng.Uniform(0, 100), 0);
      Eigen::VectorXd x(2 * k);
      for (int d = 0; d < 2 * k; ++d) x[d] = rng.Uniform(0, 100);
      WaypointPathBuilder builder(start, goal, k, interpolation, 257);
      const Path& expected = builder.Build(x);
      std::vector<double> kx{start.x()}, ky{start.y()};
      for (int i = 0; i < k; ++i) {
        kx.push_back(x[i]);
        ky.push_back(x[k + i]);
      }
      kx.push_back(goal.x());
      ky.push_back(goal.y());
      std::vector<double> px(basis.points()), py(basis.points()), moments(2 * (k + 2));
      basis.Apply(kx.data(), ky.data(), px.data(), py.data(), moments.data());
      ASSERT_EQ(static_cast<size_t>(basis.points()), expected.size()) << "k=" << k;
      for (size_t i = 0; i < expected.size(); ++i) {
        ASSERT_NEAR(px[i], expected[i].x(), 1e-9) << "k=" << k << " point " << i;
        ASSERT_NEAR(py[i], expected[i].y(), 1e-9) << "k=" << k << " point " << i;
      }
      // The path starts and ends exactly at the start and the goal.
      EXPECT_EQ(px.front(), start.x());
      EXPECT_EQ(py.back(), goal.y());
    }
  }
}

TEST(InterpolationBasisTest, ArcLengthParametersKeepUnevenKnotsFromOvershooting) {
  // Knots on a straight line, crowded at one end: with the uniform parameter the spline runs
  // back and forth along the line; with each knot's distance as its parameter it moves forward
  // only, and still passes through every knot.
  const std::vector<double> kx = {0, 1, 1.5, 2, 20, 40}, ky(kx.size(), 0.0);
  const InterpolationBasis uniform(Interpolation::kSpline, 4, 400);
  const InterpolationBasis arc(Interpolation::kSpline, kx, 400);
  std::vector<double> px(400), py(400), moments(2 * kx.size());
  auto backward_steps = [&](const InterpolationBasis& basis) {
    basis.Apply(kx.data(), ky.data(), px.data(), py.data(), moments.data());
    int backward = 0;
    for (size_t i = 1; i < px.size(); ++i) backward += px[i] < px[i - 1] - 1e-12 ? 1 : 0;
    return backward;
  };
  EXPECT_GT(backward_steps(uniform), 0);
  EXPECT_EQ(backward_steps(arc), 0);
  EXPECT_EQ(px.front(), 0.0);
  EXPECT_EQ(px.back(), 40.0);
  // A curved case: every knot is on the path (the points at the knots' parameters).
  const std::vector<double> t = {0, 2, 3, 7, 8.5, 12};
  const std::vector<double> cx = {0, 2, 3, 5, 6, 9}, cy = {0, 1, 3, 2, 5, 4};
  const InterpolationBasis curve(Interpolation::kSpline, t, 25);  // a point every 0.5
  curve.Apply(cx.data(), cy.data(), px.data(), py.data(), moments.data());
  for (size_t j = 0; j < t.size(); ++j) {
    const int i = static_cast<int>(std::lround(t[j] / 0.5));
    EXPECT_NEAR(px[i], cx[j], 1e-9) << "knot " << j;
    EXPECT_NEAR(py[i], cy[j], 1e-9) << "knot " << j;
  }
}

// Distance from p to the nearest obstacle of the world (0 inside).
double ExactDistance(const ShapeWorld& world, const Point2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Circle& c : world.circles()) best = std::min(best, SegmentCircleDistance(p, p, c));
  for (const Polygon& q : world.polygons()) {
    best = std::min(best, SegmentPolygonDistance(p, p, q.vertices));
  }
  return best;
}

TEST(ShapeDistanceFieldTest, BoundsTheTrueDistanceFromBelowAndIsClose) {
  RandomWorldOptions options;
  options.obstacle_ratio = 0.3;
  const ShapeWorld world = *RandomShapeWorld(options, 5);
  const DistanceField& field = world.distance_field();
  const double h = field.cell_size();
  EXPECT_NEAR(h, 100.0 / 256, 1e-12);
  EXPECT_LE(field.MemoryBytes(), 272u * 272u * 4u);
  Rng rng(3);
  for (int i = 0; i < 5000; ++i) {
    const Point2 p(rng.Uniform(-2.0, 102.0), rng.Uniform(-2.0, 102.0));
    const double exact = std::max(0.0, ExactDistance(world, p));
    const int cx = static_cast<int>(std::floor((p.x() - field.origin().x()) / h));
    const int cy = static_cast<int>(std::floor((p.y() - field.origin().y()) / h));
    EXPECT_GE(exact, field.CellValue(cx, cy) - DistanceField::kCellSlack * h) << p.transpose();
    // Close where the nearest obstacle is nearer than the field's edge (beyond it the field
    // only knows that the edge is clear).
    const Point2 far_corner = field.origin() + Point2(field.width(), field.height()) * h;
    const double to_edge = std::min({p.x() - field.origin().x(), p.y() - field.origin().y(),
                                     far_corner.x() - p.x(), far_corner.y() - p.y()});
    if (exact > 0 && exact + 2 * h < to_edge) {
      EXPECT_NEAR(field.Bilinear(p.x(), p.y()), exact, 2.0 * h) << p.transpose();
    }
  }
}

TEST(ShapeDistanceFieldTest, SeesObstaclesJustOutsideTheBounds) {
  // A circle outside the bounds, 1 from the right edge: the field near the edge says so.
  const ShapeWorld world = *ShapeWorld::Create({{0, 0}, {100, 100}}, {{{103, 50}, 2.0}}, {});
  const DistanceField& field = world.distance_field();
  EXPECT_NEAR(field.Bilinear(99.5, 50), 1.5, 2 * field.cell_size());
  EXPECT_GT(field.Bilinear(50, 50), 10.0);
}

Problem OpenProblem(double clearance) {
  Problem problem;
  problem.map =
      std::make_shared<Map>(*ShapeWorld::Create({{0, 0}, {100, 100}}, {{{50, 50}, 5.0}}, {}));
  problem.start = {10, 50, 0};
  problem.goal = {90, 50, 0};
  problem.clearance = clearance;
  return problem;
}

TEST(FleetObjectiveTest, StraightPathFarFromObstaclesCostsItsLength) {
  WaypointFitnessOptions options;
  options.waypoints = 1;
  options.interpolation = Interpolation::kLinear;
  options.fleet = FleetObjective{.preferred_clearance = 2.0, .turning_radius = 2.0};
  FitnessEngine engine = *FitnessEngine::Create(OpenProblem(0.5), options);
  const FleetTerms far = engine.Terms(Eigen::Vector2d(50, 80));  // a wide detour above
  EXPECT_NEAR(far.length, 2 * std::hypot(40, 30), 1e-9);
  EXPECT_EQ(far.clearance, 0.0);
  // The corner's turn is spread over its two half-segments: a radius of about 33, over 2.
  EXPECT_EQ(far.curvature, 0.0);
  EXPECT_EQ(far.violation, 0.0);
  EXPECT_TRUE(engine.Evaluate(Eigen::VectorXd(Eigen::Vector2d(50, 80))).feasible);
  // Through the circle: infeasible, the violation grows with the depth.
  const FleetTerms through = engine.Terms(Eigen::Vector2d(50, 50));
  EXPECT_GT(through.violation, 0.0);
  EXPECT_GT(through.clearance, 0.0);
  EXPECT_FALSE(engine.Evaluate(Eigen::VectorXd(Eigen::Vector2d(50, 50))).feasible);
  const FleetTerms grazing = engine.Terms(Eigen::Vector2d(50, 54));
  EXPECT_LT(grazing.violation, through.violation);
}

TEST(FleetObjectiveTest, CurvatureExcessOnACircleArc) {
  // 40 waypoints on a half circle of radius 20 around (50, 20), joined straight.
  Problem problem = OpenProblem(0.0);
  problem.map = std::make_shared<Map>(*ShapeWorld::Create({{0, 0}, {100, 100}}, {}, {}));
  problem.start = {30, 20, 0};
  problem.goal = {70, 20, 0};
  const int k = 40;
  Eigen::VectorXd x(2 * k);
  for (int i = 0; i < k; ++i) {
    const double angle = std::numbers::pi * (1.0 - (i + 1.0) / (k + 1));
    x[i] = 50 + 20 * std::cos(angle);
    x[k + i] = 20 + 20 * std::sin(angle);
  }
  WaypointFitnessOptions options;
  options.waypoints = k;
  options.interpolation = Interpolation::kLinear;
  options.fleet = FleetObjective{.turning_radius = 10.0};
  FitnessEngine loose = *FitnessEngine::Create(problem, options);
  EXPECT_EQ(loose.Terms(x).curvature, 0.0);  // radius 20 > 10
  options.fleet = FleetObjective{.turning_radius = 40.0};
  FitnessEngine tight = *FitnessEngine::Create(problem, options);
  const FleetTerms t = tight.Terms(x);
  // (1/20 - 1/40) over the arc (pi 20), less the half segments at the two ends.
  EXPECT_NEAR(t.curvature, (1.0 / 20 - 1.0 / 40) * std::numbers::pi * 20, 0.05);
}

TEST(FleetObjectiveTest, ClearanceIsContinuousAndWorksOnGrids) {
  WaypointFitnessOptions options;
  options.waypoints = 1;
  options.fleet = FleetObjective{.preferred_clearance = 3.0};
  Problem problem = OpenProblem(0.0);
  problem.map = std::make_shared<Map>(*RasterizeShapeWorld(*problem.map->world(), 1.0));
  problem.start = {10.5, 50.5, 0};
  problem.goal = {89.5, 50.5, 0};
  FitnessEngine engine = *FitnessEngine::Create(problem, options);
  // The spline over the circle's top: the shortfall shrinks as the waypoint rises, smoothly.
  const FleetTerms low = engine.Terms(Eigen::Vector2d(50, 56));
  const FleetTerms high = engine.Terms(Eigen::Vector2d(50, 60));
  EXPECT_GT(low.clearance, high.clearance);
  // Steps of 1e-4: the fitness moves by its slope (about 10) times the step; a nearest-cell
  // read of the field would jump by a fraction of a cell times the segment length.
  double previous = engine.Evaluate(Eigen::VectorXd(Eigen::Vector2d(50, 56))).fitness;
  double largest = 0.0;
  for (int i = 1; i <= 20000; ++i) {
    const double y = 56 + 1e-4 * i;
    const double f = engine.Evaluate(Eigen::VectorXd(Eigen::Vector2d(50, y))).fitness;
    largest = std::max(largest, std::abs(f - previous));
    previous = f;
  }
  EXPECT_LT(largest, 5e-3);
}

// The component labels of a grid are read per cell, so a path may cross only cells that are
// farther than the hard clearance from every blocked cell while it passes closer than that to
// one of them. Feasibility must still be the collision checker's verdict on the decoded path.
TEST(FleetObjectiveTest, FeasibleIsTheCollisionCheckersVerdictOnGrids) {
  for (const double resolution : {1.0, 0.5}) {
    RandomGridOptions grid_options;
    grid_options.width = 48;
    grid_options.height = 48;
    grid_options.obstacle_ratio = 0.03;
    grid_options.resolution = resolution;
    grid_options.keep_free = {{4, 4}, {43, 30}};
    for (const double cells : {0.3, 0.5}) {
      Problem problem;
      problem.map = std::make_shared<Map>(*RandomGrid(grid_options, 5));
      problem.start = {4.5 * resolution, 4.5 * resolution, 0};
      problem.goal = {43.5 * resolution, 30.5 * resolution, 0};
      problem.clearance = cells * resolution;
      WaypointFitnessOptions options;
      options.waypoints = 3;
      options.fleet = FleetObjective{.preferred_clearance = 2.0 * problem.clearance};
      FitnessEngine engine = *FitnessEngine::Create(problem, options);
      const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*problem.map);
      Rng rng(3);
      int feasible = 0, infeasible = 0;
      std::vector<Eigen::VectorXd> clear;
      Eigen::VectorXd x(6);
      Path path;
      for (int trial = 0; trial < 3000; ++trial) {
        if (trial % 2 == 1 && !clear.empty()) {
          // A clear path moved a little: one that grazes the clearance.
          x = clear[rng.UniformInt(0, static_cast<int64_t>(clear.size()) - 1)];
          for (int d = 0; d < 6; ++d) x[d] += rng.Uniform(-0.4, 0.4) * resolution;
        } else {
          for (int i = 0; i < 3; ++i) {
            const Point3 on = problem.start + (problem.goal - problem.start) * (i + 1) / 4.0;
            x[i] = on.x() + rng.Uniform(-6.0, 6.0) * resolution;
            x[3 + i] = on.y() + rng.Uniform(-6.0, 6.0) * resolution;
          }
        }
        engine.Decode(x, path);
        const bool free = checker->PathFree(path, problem.clearance);
        ASSERT_EQ(engine.Evaluate(x).feasible, free)
            << "resolution " << resolution << ", clearance " << problem.clearance << ", trial "
            << trial;
        if (free) {
          ++feasible;
          if (clear.size() < 200) clear.push_back(x);
        } else {
          ++infeasible;
        }
      }
      EXPECT_GT(feasible, 100) << "clearance " << problem.clearance;
      EXPECT_GT(infeasible, 100) << "clearance " << problem.clearance;
    }
  }
}

TEST(FleetObjectiveTest, RejectsBadWeights) {
  WaypointFitnessOptions options;
  options.fleet = FleetObjective{.clearance_weight = -1.0};
  absl::StatusOr<FitnessEngine> engine = FitnessEngine::Create(OpenProblem(0), options);
  ASSERT_FALSE(engine.ok());
  EXPECT_NE(engine.status().message().find("clearance_weight"), std::string::npos);
}

TEST(FleetObjectiveTest, AnyPathIsReadAsTheEngineReadsItsOwn) {
  Problem problem = OpenProblem(0.5);
  problem.fleet = FleetObjective{.preferred_clearance = 3.0, .turning_radius = 4.0};
  WaypointFitnessOptions options;
  options.waypoints = 1;
  options.samples = 400;
  options.fleet = problem.fleet;
  FitnessEngine engine = *FitnessEngine::Create(problem, options);
  for (const Eigen::Vector2d& waypoint : {Eigen::Vector2d(50, 58), Eigen::Vector2d(50, 50)}) {
    Path path;
    engine.Decode(waypoint, path);
    const FleetTerms own = engine.Terms(waypoint);
    const absl::StatusOr<FleetTerms> any = EvaluateFleetObjective(problem, path);
    ASSERT_TRUE(any.ok()) << any.status();
    EXPECT_NEAR(any->length, own.length, 1e-9);
    // The same points, and more where the samples are farther apart than half a field cell.
    EXPECT_NEAR(any->clearance, own.clearance, 0.01 * own.clearance);
    EXPECT_NEAR(any->curvature, own.curvature, 1e-9);
    EXPECT_NEAR(any->violation, own.violation, 0.01 * own.violation);
  }
  // A corner: the clearance terms read between its two vertices too.
  const absl::StatusOr<FleetTerms> corner =
      EvaluateFleetObjective(problem, {{10, 50, 0}, {50, 50, 0}, {90, 50, 0}});
  ASSERT_TRUE(corner.ok());
  EXPECT_GT(corner->violation, 0.0);
  EXPECT_FALSE(EvaluateFleetObjective(Problem{}, {}).ok());
}

}  // namespace
}  // namespace swarmplan
