#include "bench/bench_runner.h"

#include <cmath>
#include <sstream>

#include "absl/status/status.h"
#include "gtest/gtest.h"
#include "tests/unit/test_support.h"

namespace swarmplan::bench {
namespace {

// Plans the straight segment from start to goal; reports the seed as its iteration count so
// tests can see which seed a run got.
class StraightPlanner final : public Planner {
 public:
  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken&, Observer&) override {
    SearchResult result;
    result.found = true;
    result.path = {problem.start, problem.goal};
    result.iterations = static_cast<int>(problem.seed);
    result.evaluations = 10;
    return result;
  }
};

class BrokenPlanner final : public Planner {
 public:
  absl::StatusOr<SearchResult> Solve(const Problem&, const StopToken&, Observer&) override {
    return absl::InternalError("broken on purpose");
  }
};

Registry TestRegistry() {
  Registry registry;
  PlannerInfo straight;
  straight.id = "straight";
  straight.description = "straight segment";
  straight.map_kinds = {MapKind::kOccupancyGrid};
  straight.params = {ParamSpec::Int("weight", 1, 1, 10, "", "unused"),
                     ParamSpec::Enum("connectivity", "8", {"8", "4"}, "unused")};
  straight.factory = [](const ParamSet&) { return std::make_unique<StraightPlanner>(); };
  EXPECT_TRUE(registry.Register(straight).ok());

  PlannerInfo broken;
  broken.id = "broken";
  broken.description = "always fails";
  broken.map_kinds = {MapKind::kOccupancyGrid, MapKind::kShapeWorld};
  broken.factory = [](const ParamSet&) { return std::make_unique<BrokenPlanner>(); };
  EXPECT_TRUE(registry.Register(broken).ok());

  PlannerInfo shapes_only;
  shapes_only.id = "shapes-only";
  shapes_only.description = "shape worlds only";
  shapes_only.map_kinds = {MapKind::kShapeWorld};
  shapes_only.factory = [](const ParamSet&) { return std::make_unique<StraightPlanner>(); };
  EXPECT_TRUE(registry.Register(shapes_only).ok());
  return registry;
}

// A free 10 × 10 grid with cell (0, 0) blocked; resolution 0.5, origin (10, 20).
MapPtr SmallGrid() {
  std::vector<int8_t> cells(100, OccupancyGrid::kFree);
  cells[0] = OccupancyGrid::kOccupied;
  absl::StatusOr<OccupancyGrid> grid =
      OccupancyGrid::Create(10, 10, std::move(cells), 0.5, Point2(10, 20));
  EXPECT_TRUE(grid.ok()) << grid.status();
  return std::make_shared<const Map>(*std::move(grid));
}

Scenario MakeScenario(Cell start, Cell goal, double optimal) {
  Scenario s;
  s.map_name = "small.map";
  s.width = 10;
  s.height = 10;
  s.start = start;
  s.goal = goal;
  s.optimal_length = optimal;
  return s;
}

BenchProblem Problem(const MapPtr& map, Point3 start, Point3 goal,
                     std::optional<double> optimal = std::nullopt) {
  BenchProblem p;
  p.map_name = "small.map";
  p.map = map;
  p.scenario = "0";
  p.start = start;
  p.goal = goal;
  p.optimal = optimal;
  return p;
}

TEST(BenchRunnerTest, ScenarioProblemsUseCellCentresAndWorldUnits) {
  const MapPtr map = SmallGrid();
  const std::vector<Scenario> scenarios = {MakeScenario({1, 2}, {5, 2}, 4.0)};
  absl::StatusOr<std::vector<BenchProblem>> problems = ScenarioProblems(
      "small.map", map, "small.map.scen", scenarios, {ScenarioSelection::Mode::kAll, 0});
  ASSERT_TRUE(problems.ok()) << problems.status();
  ASSERT_EQ(problems->size(), 1u);
  const BenchProblem& p = (*problems)[0];
  EXPECT_EQ(p.map_name, "small.map");
  EXPECT_EQ(p.scenario, "0");
  EXPECT_EQ(p.start, Point3(10.75, 21.25, 0));
  EXPECT_EQ(p.goal, Point3(12.75, 21.25, 0));
  EXPECT_EQ(p.scen_optimal, 2.0);
  EXPECT_FALSE(p.optimal.has_value());  // AddOptima fills it
}

TEST(BenchRunnerTest, ScenarioProblemsRejectAnotherSizeOrMapKind) {
  const std::vector<Scenario> scenarios = {MakeScenario({1, 2}, {5, 2}, 4.0)};
  std::vector<Scenario> wrong = scenarios;
  wrong[0].width = 11;
  absl::StatusOr<std::vector<BenchProblem>> sized =
      ScenarioProblems("small.map", SmallGrid(), "x.scen", wrong, {});
  ASSERT_FALSE(sized.ok());
  EXPECT_NE(sized.status().message().find("x.scen"), absl::string_view::npos);
  EXPECT_NE(sized.status().message().find("11x10"), absl::string_view::npos);

  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create({Point2(0, 0), Point2(10, 10)}, {}, {});
  ASSERT_TRUE(world.ok()) << world.status();
  absl::StatusOr<std::vector<BenchProblem>> kind = ScenarioProblems(
      "w.json", std::make_shared<const Map>(*std::move(world)), "x.scen", scenarios, {});
  ASSERT_FALSE(kind.ok());
  EXPECT_NE(kind.status().message().find("grid"), absl::string_view::npos);
}

TEST(BenchRunnerTest, PlannersForExpandsAllByMapKind) {
  const Registry registry = TestRegistry();
  EXPECT_EQ(PlannersFor(registry, {"all"}, MapKind::kOccupancyGrid),
            (std::vector<std::string>{"straight", "broken"}));
  EXPECT_EQ(PlannersFor(registry, {"shapes-only", "all"}, MapKind::kShapeWorld),
            (std::vector<std::string>{"shapes-only", "broken"}));
  // A named planner stays even when it cannot plan on the map: its rows say why.
  EXPECT_EQ(PlannersFor(registry, {"shapes-only"}, MapKind::kOccupancyGrid),
            std::vector<std::string>{"shapes-only"});
  EXPECT_TRUE(PlannersFor(registry, {"all"}, MapKind::kTerrain).empty());
}

TEST(BenchRunnerTest, ResolvePlannerParamsTypesThemBySchema) {
  const Registry registry = TestRegistry();
  BenchOptions options;
  options.planners = {"straight"};
  options.params["straight"] = {{"weight", "3"}, {"connectivity", "4"}};
  absl::StatusOr<PlannerParams> params = ResolvePlannerParams(registry, options);
  ASSERT_TRUE(params.ok()) << params.status();
  EXPECT_EQ(params->at("straight").at("weight"), ParamValue(int64_t{3}));
  EXPECT_EQ(params->at("straight").at("connectivity"), ParamValue(std::string("4")));

  options.planners = {"all"};
  EXPECT_TRUE(ResolvePlannerParams(registry, options).ok());
}

TEST(BenchRunnerTest, ResolvePlannerParamsNamesTheProblem) {
  const Registry registry = TestRegistry();
  auto error_of = [&registry](std::vector<std::string> planners, RawParams raw) {
    BenchOptions options;
    options.planners = std::move(planners);
    options.params = std::move(raw);
    absl::StatusOr<PlannerParams> params = ResolvePlannerParams(registry, options);
    EXPECT_FALSE(params.ok());
    EXPECT_EQ(params.status().code(), absl::StatusCode::kInvalidArgument);
    return std::string(params.status().message());
  };
  EXPECT_NE(error_of({"straight", "nope"}, {}).find("nope"), std::string::npos);
  EXPECT_NE(error_of({"straight"}, {{"nope", {{"x", "1"}}}}).find("nope"), std::string::npos);
  EXPECT_NE(error_of({"straight"}, {{"straight", {{"weight", "30"}}}}).find("weight"),
            std::string::npos);
  EXPECT_NE(error_of({"straight"}, {{"straight", {{"weight", "heavy"}}}}).find("straight.weight"),
            std::string::npos);
  EXPECT_NE(error_of({"straight"}, {{"straight", {{"connectivity", "6"}}}}).find("connectivity"),
            std::string::npos);
  EXPECT_NE(error_of({"straight"}, {{"straight", {{"colour", "red"}}}}).find("colour"),
            std::string::npos);
  // Parameters for a planner that is not selected are a mistake, not silently ignored.
  EXPECT_NE(error_of({"straight"}, {{"broken", {}}}).find("broken"), std::string::npos);
}

TEST(BenchRunnerTest, RunOnceRecordsTheMetricsOfRunPlan) {
  const Registry registry = TestRegistry();
  BenchOptions options;
  std::string note;
  const RunRecord r = RunOnce(registry, Problem(SmallGrid(), {11, 21, 0}, {14, 25, 0}, 4.0),
                              "straight", {}, 9, options, &note);
  EXPECT_TRUE(note.empty()) << note;
  EXPECT_EQ(r.map, "small.map");
  EXPECT_EQ(r.planner, "straight");
  EXPECT_EQ(r.seed, 9u);
  EXPECT_TRUE(r.success);
  ASSERT_TRUE(r.length.has_value());
  EXPECT_NEAR(*r.length, 5.0, 1e-9);
  EXPECT_EQ(r.optimal, 4.0);
  ASSERT_TRUE(r.ratio.has_value());
  EXPECT_NEAR(*r.ratio, 1.25, 1e-9);
  ASSERT_TRUE(r.min_clearance.has_value());
  EXPECT_GT(*r.min_clearance, 0.0);
  EXPECT_EQ(r.iterations, 9);  // the planner saw the seed
  EXPECT_EQ(r.evaluations, 10);
  EXPECT_GE(r.wall_seconds, 0.0);
}

TEST(BenchRunnerTest, RunOnceTurnsARejectedRequestIntoAFailedRow) {
  const Registry registry = TestRegistry();
  BenchOptions options;
  std::string note;
  // The grid covers [10, 15] x [20, 25].
  const RunRecord r = RunOnce(registry, Problem(SmallGrid(), {9, 21, 0}, {14, 25, 0}, 4.0),
                              "straight", {}, 1, options, &note);
  EXPECT_FALSE(r.success);
  EXPECT_FALSE(r.length.has_value());
  EXPECT_FALSE(r.ratio.has_value());
  EXPECT_EQ(r.optimal, 4.0);
  EXPECT_NE(note.find("FAILED_PRECONDITION"), std::string::npos) << note;
  EXPECT_NE(note.find("start"), std::string::npos) << note;
}

TEST(BenchRunnerTest, RunOnceCountsACollidingPathAsAFailure) {
  const Registry registry = TestRegistry();
  BenchOptions options;
  std::string note;
  // Both ends are free; the segment between them crosses the blocked cell (0, 0).
  const RunRecord r =
      RunOnce(registry, Problem(SmallGrid(), {10.1, 20.75, 0}, {10.9, 20.1, 0}, 1.0), "straight",
              {}, 1, options, &note);
  EXPECT_FALSE(r.success);
  EXPECT_TRUE(r.length.has_value());
  EXPECT_FALSE(r.ratio.has_value());
  EXPECT_NE(note.find("not collision-free"), std::string::npos) << note;
}

TEST(BenchRunnerTest, RunOnceTurnsAPlannerErrorIntoAFailedRow) {
  const Registry registry = TestRegistry();
  BenchOptions options;
  std::string note;
  const RunRecord r = RunOnce(registry, Problem(SmallGrid(), {11, 21, 0}, {14, 25, 0}), "broken",
                              {}, 1, options, &note);
  EXPECT_FALSE(r.success);
  EXPECT_NE(note.find("broken on purpose"), std::string::npos) << note;
}

TEST(BenchRunnerTest, RunBenchRunsEveryProblemPlannerAndSeed) {
  const Registry registry = TestRegistry();
  BenchOptions options;
  options.planners = {"straight", "shapes-only"};
  options.runs = 3;
  options.seed = 5;
  const MapPtr map = SmallGrid();
  std::vector<BenchProblem> problems = {Problem(map, {11, 21, 0}, {14, 25, 0}),
                                        Problem(map, {12, 22, 0}, {13, 23, 0})};
  problems[1].scenario = "1";
  std::vector<RunRecord> records;
  std::ostringstream notes;
  RunBench(
      registry, problems, options, {}, [&](const RunRecord& r) { records.push_back(r); }, notes);
  ASSERT_EQ(records.size(), 12u);
  EXPECT_EQ(records[0].scenario, "0");
  EXPECT_EQ(records[0].planner, "straight");
  EXPECT_EQ(records[0].seed, 5u);
  EXPECT_EQ(records[1].seed, 6u);
  EXPECT_EQ(records[2].seed, 7u);
  EXPECT_EQ(records[2].iterations, 7);
  EXPECT_TRUE(records[2].success);
  EXPECT_EQ(records[3].planner, "shapes-only");
  EXPECT_FALSE(records[3].success);  // cannot plan on a grid: a failed row, not a crash
  EXPECT_EQ(records[6].scenario, "1");
  EXPECT_NE(notes.str().find("shapes-only"), std::string::npos);
  EXPECT_NE(notes.str().find("FAILED_PRECONDITION"), std::string::npos);
  EXPECT_NE(notes.str().find("occupancy-grid"), std::string::npos);
}

// The acceptance check of the runner: A* through the whole path (loader, scenarios, RunPlan)
// reproduces the optimal lengths of a Moving AI scenario file.
TEST(BenchRunnerTest, AStarReproducesMovingAiOptimaOnArena) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/arena.map.scen");
  if (DefaultRegistry().Find("astar") == nullptr) GTEST_SKIP() << "astar is not registered";
  const std::string dir = swarmplan::testing::BenchmarksDir() + "/movingai/";
  BenchOptions options;
  options.planners = {"astar"};
  options.maps = {dir + "arena.map"};
  options.scenario_files = {dir + "arena.map.scen"};
  std::ostringstream notes;
  absl::StatusOr<std::vector<BenchProblem>> problems = LoadProblems(options, notes);
  ASSERT_TRUE(problems.ok()) << problems.status();
  ASSERT_GE(problems->size(), 10u);  // one per bucket
  AddOptima(DefaultRegistry(), absl::Seconds(10), 0.0, *problems, notes);
  std::vector<RunRecord> records;
  RunBench(
      DefaultRegistry(), *problems, options, {}, [&](const RunRecord& r) { records.push_back(r); },
      notes);
  ASSERT_EQ(records.size(), problems->size());
  for (const RunRecord& r : records) {
    ASSERT_TRUE(r.success) << "scenario " << r.scenario << ": " << notes.str();
    ASSERT_TRUE(r.length.has_value() && r.scen_optimal.has_value());
    EXPECT_NEAR(*r.length / *r.scen_optimal, 1.0, 1e-4) << "scenario " << r.scenario;
    // Against the exact any-angle optimum an 8-connected path is never shorter.
    ASSERT_TRUE(r.ratio.has_value()) << notes.str();
    EXPECT_GE(*r.ratio, 1.0 - 1e-9) << "scenario " << r.scenario;
  }
}

}  // namespace
}  // namespace swarmplan::bench
