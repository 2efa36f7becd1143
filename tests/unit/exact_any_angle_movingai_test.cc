#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "core/geometry/collision.h"
#include "core/map/io/map_io.h"
#include "core/map/map.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"
#include "tests/unit/plan_test_support.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

using ::swarmplan::testing::NullObserver;

absl::StatusOr<PlanResult> Plan(const std::string& algorithm, const MapPtr& map,
                                const Point2& start, const Point2& goal, double clearance = 0,
                                const ParamValues& params = {}) {
  return ::swarmplan::testing::PlanOnMap(algorithm, map, start, goal, clearance, params);
}

// Three scenarios per file, from buckets spread from the shortest to the middle one (longer
// ones make theta-star, not the exact planner, too slow for a unit test).
std::vector<Scenario> SpreadSample(const std::vector<Scenario>& scenarios) {
  std::map<int, const Scenario*> first_of_bucket;
  for (const Scenario& s : scenarios) first_of_bucket.try_emplace(s.bucket, &s);
  std::vector<const Scenario*> buckets;
  for (const auto& [bucket, s] : first_of_bucket) buckets.push_back(s);
  std::vector<Scenario> sample;
  constexpr size_t kPerFile = 3;
  for (size_t k = 0; k < kPerFile && !buckets.empty(); ++k) {
    sample.push_back(*buckets[k * (buckets.size() - 1) / (2 * (kPerFile - 1))]);
  }
  return sample;
}

// The exact optimum is never longer than theta-star nor than the octile optimum of the .scen
// file, joins the requested points exactly and is collision-free.
TEST(ExactAnyAngleMovingAiTest, NeverLongerThanThetaStarOrTheOctileOptimum) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai");
  const std::string dir = ::swarmplan::testing::BenchmarksDir() + "/movingai";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".map") continue;
    const std::string scen = entry.path().string() + ".scen";
    if (!std::filesystem::exists(scen)) continue;
    SCOPED_TRACE(entry.path().filename().string());
    absl::StatusOr<Map> loaded = LoadMapFile(entry.path().string());
    ASSERT_TRUE(loaded.ok()) << loaded.status();
    const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
    const OccupancyGrid& grid = *map->grid();
    const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*map);
    absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(scen);
    ASSERT_TRUE(scenarios.ok()) << scenarios.status();
    for (const Scenario& s : SpreadSample(*scenarios)) {
      SCOPED_TRACE(::testing::Message() << "bucket " << s.bucket);
      const Point2 start = grid.CellCenter(s.start), goal = grid.CellCenter(s.goal);
      absl::StatusOr<PlanResult> exact = Plan("exact-any-angle", map, start, goal, 0.0);
      absl::StatusOr<PlanResult> theta = Plan("theta-star", map, start, goal, 0.0);
      ASSERT_TRUE(exact.ok()) << exact.status();
      ASSERT_TRUE(theta.ok()) << theta.status();
      ASSERT_TRUE(exact->found);
      ASSERT_TRUE(theta->found);
      const Path& path = exact->raw_path;
      EXPECT_EQ(path.front(), Point3(start.x(), start.y(), 0));
      EXPECT_EQ(path.back(), Point3(goal.x(), goal.y(), 0));
      EXPECT_TRUE(checker->PathFree(path, 0.0));
      const double length = PathLength(path);
      EXPECT_LE(length, PathLength(theta->raw_path) * (1 + 1e-9));
      EXPECT_LE(length, s.optimal_length * (1 + 1e-4));
      EXPECT_GE(length, (goal - start).norm() - 1e-9);
      ++checked;
    }
  }
  RecordProperty("scenarios_checked", checked);
}

TEST(ExactAnyAngleMovingAiTest, KeepsTheClearance) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/den312d.map");
  const std::string dir = ::swarmplan::testing::BenchmarksDir() + "/movingai";
  absl::StatusOr<Map> loaded = LoadMapFile(dir + "/den312d.map");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*map);
  absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(dir + "/den312d.map.scen");
  ASSERT_TRUE(scenarios.ok()) << scenarios.status();
  int found = 0;
  for (const Scenario& s : SpreadSample(*scenarios)) {
    const Point2 start = map->grid()->CellCenter(s.start), goal = map->grid()->CellCenter(s.goal);
    absl::StatusOr<PlanResult> result = Plan("exact-any-angle", map, start, goal, 0.8);
    if (!result.ok()) {
      EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
      continue;
    }
    if (!result->found) continue;
    ++found;
    EXPECT_TRUE(checker->PathFree(result->raw_path, 0.8)) << "bucket " << s.bucket;
  }
  EXPECT_GT(found, 0);
}

// With a clearance the optimum lies between the lower bound and the path returned; theta-star's
// path keeps the clearance, so it is never shorter than the lower bound. On this query the upper
// bound's sub-cells miss a diagonal gap between two blocked cells that theta-star passes.
TEST(ExactAnyAngleMovingAiTest, ClearanceOptimumIsBracketedOnBerlin) {
  SWARMPLAN_REQUIRE_BENCHMARKS("movingai/Berlin_0_256.map");
  absl::StatusOr<Map> loaded =
      LoadMapFile(::swarmplan::testing::BenchmarksDir() + "/movingai/Berlin_0_256.map");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*map);
  const Point2 start(26.5, 151.5), goal(243.5, 222.5);
  constexpr double kClearance = 0.5;
  absl::StatusOr<PlanResult> upper = Plan("exact-any-angle", map, start, goal, kClearance);
  absl::StatusOr<PlanResult> lower =
      Plan("exact-any-angle", map, start, goal, kClearance, {{"bound", std::string("lower")}});
  absl::StatusOr<PlanResult> theta = Plan("theta-star", map, start, goal, kClearance);
  ASSERT_TRUE(upper.ok()) << upper.status();
  ASSERT_TRUE(lower.ok()) << lower.status();
  ASSERT_TRUE(theta.ok()) << theta.status();
  ASSERT_TRUE(upper->found && lower->found && theta->found);
  const Path& path = upper->raw_path;
  EXPECT_EQ(path.front(), Point3(start.x(), start.y(), 0));
  EXPECT_EQ(path.back(), Point3(goal.x(), goal.y(), 0));
  EXPECT_TRUE(checker->PathFree(path, kClearance));
  EXPECT_TRUE(checker->PathFree(theta->raw_path, kClearance));
  const double u = PathLength(path), l = PathLength(lower->raw_path);
  const double t = PathLength(theta->raw_path);
  EXPECT_LE(l, t * (1 + 1e-9));
  EXPECT_LE(l, u * (1 + 1e-9));
  EXPECT_LE(u, t * (1 + 1e-9));
  RecordProperty("upper", absl::StrCat(u));
  RecordProperty("lower", absl::StrCat(l));
  RecordProperty("theta", absl::StrCat(t));
}

}  // namespace
}  // namespace swarmplan
