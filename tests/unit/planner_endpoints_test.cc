// Every registered planner on a small occupancy grid and a small shape world, with a start and
// a goal off the cell centres: the raw path begins exactly at the start and ends exactly at the
// goal, or the planner says it found nothing.

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "absl/time/time.h"
#include "core/geometry/primitives.h"
#include "core/path_metrics.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

MapPtr SmallGrid() {
  return ::swarmplan::testing::GridMap({
      "............",  //
      "............",  //
      "....#.......",  //
      "....#...#...",  //
      "....#...#...",  //
      "....#...#...",  //
      "........#...",  //
      "............",  //
      "............",  //
      "............",  //
  });
}

MapPtr SmallWorld() {
  absl::StatusOr<ShapeWorld> world = ShapeWorld::Create(
      Bounds2{Point2(0, 0), Point2(12, 10)}, {Circle{Point2(8.2, 4.4), 1.6}},
      {Polygon{{Point2(3.9, 2.1), Point2(5.2, 2.1), Point2(5.2, 6.3), Point2(3.9, 6.3)}}});
  EXPECT_TRUE(world.ok()) << world.status();
  return std::make_shared<const Map>(*std::move(world));
}

struct Case {
  const char* name;
  MapPtr map;
};

TEST(PlannerEndpointsTest, EveryPlannerStartsAndEndsExactlyWhereAsked) {
  const Point3 start(1.3, 1.7, 0.0);
  const Point3 goal(10.6, 8.2, 0.0);
  const std::vector<Case> cases = {{"occupancy-grid", SmallGrid()}, {"shape-world", SmallWorld()}};
  int runs = 0;
  std::string table;
  for (const PlannerInfo& info : DefaultRegistry().planners()) {
    for (const Case& c : cases) {
      if (!info.Supports(c.map->kind())) continue;
      SCOPED_TRACE(info.id + " on " + c.name);
      PlanRequest request;
      request.algorithm = info.id;
      request.problem.map = c.map;
      request.problem.start = start;
      request.problem.goal = goal;
      request.problem.seed = 3;
      request.problem.limits.max_iterations = 60;
      request.problem.limits.time_budget = absl::Seconds(1);
      NullObserver observer;
      absl::StatusOr<PlanResult> r = RunPlan(DefaultRegistry(), request, StopToken(), observer);
      ASSERT_TRUE(r.ok()) << r.status();
      ++runs;
      table += info.id + " / " + c.name + ": " + (r->found ? "found" : "nothing") + "\n";
      if (!r->found) continue;
      ASSERT_FALSE(r->raw_path.empty());
      EXPECT_EQ(r->raw_path.front(), start);
      EXPECT_EQ(r->raw_path.back(), goal);
      EXPECT_TRUE(r->raw_metrics.collision_free);
      EXPECT_GE(r->raw_metrics.min_clearance, 0.0);
      if (info.encoding == Encoding::kGridNodes) {
        // The fitness of a grid path is the length of the world path, joins included.
        EXPECT_NEAR(r->fitness, PathLength(r->raw_path), 1e-9);
      }
    }
  }
  EXPECT_GT(runs, 20);
  std::cout << table;
}

}  // namespace
}  // namespace swarmplan
