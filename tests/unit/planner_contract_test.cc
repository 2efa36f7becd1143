// The contract every registered planner passes, on every map kind it claims: small generated
// maps and real maps from ../shared/benchmarks. For each run: the path joins start and goal
// exactly, keeps the clearance by a checker written for this test, is not shorter than the
// exact optimum, the same seed gives the same path bit for bit, OnIteration comes once per
// iteration with a non-increasing best, a tripped stop token ends the search within one
// iteration, and a planner that finds nothing says so. On the real 2D maps every planner that
// starts from seed paths by default (`init=seeded`) must find a path, within 1.05 of the optimum
// where the map asks for no clearance; the others may find none, and each test prints which
// planners succeeded on its map so the gap stays visible.

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/map/generate.h"
#include "core/map/io/map_io.h"
#include "core/optimum.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"
#include "tests/unit/beetle_test_support.h"
#include "tests/unit/contract_checks.h"
#include "tests/unit/test_support.h"

namespace swarmplan {
namespace {

constexpr int kIterations = 15;  // enough to exercise every loop, small enough for the sanitizers
constexpr int kCancelAt = 1;

struct ContractMap {
  std::string name;
  std::string benchmark_file;  // under ../shared/benchmarks; empty for a generated map
  std::function<absl::StatusOr<Map>()> make;
  Point3 start;
  Point3 goal;
  double clearance = 0.0;
  // Terrain: start and goal from the loaded map (world coordinates of cells, a height above
  // the ground); unset for 2D maps, whose points are given.
  std::function<void(const Terrain&, Point3&, Point3&)> place;
};

// Start and goal `height` above the ground at cells (x0, y0) and (x1, y1).
std::function<void(const Terrain&, Point3&, Point3&)> AboveCells(int x0, int y0, int x1, int y1,
                                                                 double height) {
  return [=](const Terrain& t, Point3& start, Point3& goal) {
    const Point2 a = t.CellCentre(x0, y0), b = t.CellCentre(x1, y1);
    start = Point3(a.x(), a.y(), t.HeightAt(x0, y0) + height);
    goal = Point3(b.x(), b.y(), t.HeightAt(x1, y1) + height);
  };
}

using beetle_testing::RecordingObserver;

// The path's clearance by the checks of contract_checks.h; -1 outside the map.
double IndependentClearance(const Map& map, const Path& path) {
  if (const OccupancyGrid* grid = map.grid()) return contract::GridPathClearance(*grid, path);
  if (const ShapeWorld* world = map.world()) return contract::WorldPathClearance(*world, path);
  return contract::TerrainPathClearance(*map.terrain(), path);
}

double PolylineLength(const Path& path) {
  double length = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) length += (path[i + 1] - path[i]).norm();
  return length;
}

std::vector<ContractMap> ContractMaps() {
  std::vector<ContractMap> maps;
  maps.push_back({"generated grid 32x32", "",
                  [] {
                    RandomGridOptions o;
                    o.width = o.height = 32;
                    o.obstacle_ratio = 0.2;
                    o.block_size = 3;
                    o.keep_free = {{2, 2}, {29, 28}};
                    absl::StatusOr<OccupancyGrid> grid = RandomGrid(o, 11);
                    if (!grid.ok()) return absl::StatusOr<Map>(grid.status());
                    return absl::StatusOr<Map>(Map(*std::move(grid)));
                  },
                  Point3(2.3, 2.8, 0), Point3(29.6, 28.2, 0), 0.0, nullptr});
  maps.push_back({"generated shape world", "",
                  [] {
                    RandomWorldOptions o;
                    o.bounds = {Point2(0, 0), Point2(40, 40)};
                    o.obstacle_ratio = 0.2;
                    o.keep_clear = {Point2(3, 3), Point2(37, 36)};
                    o.keep_clear_radius = 2.0;
                    absl::StatusOr<ShapeWorld> world = RandomShapeWorld(o, 5);
                    if (!world.ok()) return absl::StatusOr<Map>(world.status());
                    return absl::StatusOr<Map>(Map(*std::move(world)));
                  },
                  Point3(3, 3, 0), Point3(37, 36, 0), 0.3, nullptr});
  maps.push_back({"arena (Moving AI)", "movingai/arena.map",
                  [] { return LoadMapFile(testing::BenchmarksDir() + "/movingai/arena.map"); },
                  Point3(4.5, 20.5, 0), Point3(44.5, 30.5, 0), 0.0, nullptr});
  maps.push_back(
      {"Berlin_0_256 (Moving AI)", "movingai/Berlin_0_256.map",
       [] { return LoadMapFile(testing::BenchmarksDir() + "/movingai/Berlin_0_256.map"); },
       Point3(10.5, 176.5, 0), Point3(254.5, 226.5, 0), 0.0, nullptr});
  maps.push_back(
      {"parking1 (Bench-MR)", "polygons/parking1.geojson",
       [] { return LoadMapFile(testing::BenchmarksDir() + "/polygons/parking1.geojson"); },
       Point3(1.0, 7.2, 0), Point3(17.6, 7.2, 0), 0.1, nullptr});
  maps.push_back({"generated terrain 24x16",
                  "",
                  [] {
                    std::vector<double> heights;
                    for (int y = 0; y < 16; ++y) {
                      for (int x = 0; x < 24; ++x) {
                        heights.push_back(
                            10 + 6 * std::exp(-((x - 12) * (x - 12) + (y - 8) * (y - 8)) / 18.0));
                      }
                    }
                    absl::StatusOr<Terrain> t =
                        Terrain::Create(24, 16, std::move(heights), 2.0, Point2(100, 50));
                    if (!t.ok()) return absl::StatusOr<Map>(t.status());
                    return absl::StatusOr<Map>(Map(*std::move(t)));
                  },
                  {},
                  {},
                  0.5,
                  AboveCells(1, 8, 22, 8, 1.5)});
  maps.push_back(
      {"kootenai DEM",
       "terrain/DEM-kootenai_37x50_1x1.asc",
       [] { return LoadMapFile(testing::BenchmarksDir() + "/terrain/DEM-kootenai_37x50_1x1.asc"); },
       {},
       {},
       0.5,
       AboveCells(2, 18, 47, 18, 1.5)});
  return maps;
}

class PlannerContractTest : public ::testing::TestWithParam<int> {};

// The planner starts from seed paths unless asked otherwise.
bool SeededByDefault(const PlannerInfo& info) {
  for (const ParamSpec& spec : info.params) {
    if (spec.name != "init") continue;
    const std::string* value = std::get_if<std::string>(&spec.default_value);
    return value != nullptr && *value == "seeded";
  }
  return false;
}

TEST_P(PlannerContractTest, EveryPlannerKeepsTheContract) {
  const ContractMap spec_given = ContractMaps()[GetParam()];
  if (!spec_given.benchmark_file.empty()) {
    SWARMPLAN_REQUIRE_BENCHMARKS(spec_given.benchmark_file);
  }
  absl::StatusOr<Map> loaded = spec_given.make();
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
  ContractMap spec = spec_given;
  if (spec.place) spec.place(*map->terrain(), spec.start, spec.goal);

  Problem problem;
  problem.map = map;
  problem.start = spec.start;
  problem.goal = spec.goal;
  problem.clearance = spec.clearance;
  problem.limits.max_iterations = kIterations;
  problem.seed = 7;

  Problem unobstructed = problem;
  unobstructed.clearance = 0.0;  // the optimum without clearance bounds every path from below
  const Optimum optimum = ComputeOptimum(DefaultRegistry(), unobstructed, absl::Seconds(30));
  ASSERT_TRUE(optimum.known) << optimum.planner << ": " << optimum.reason;

  std::string table;
  int claimed = 0, succeeded = 0;
  for (const PlannerInfo& info : DefaultRegistry().planners()) {
    if (!info.Supports(map->kind())) continue;
    ++claimed;
    SCOPED_TRACE(info.id + " on " + spec.name);
    PlanRequest request;
    request.algorithm = info.id;
    request.problem = problem;

    RecordingObserver observer;
    absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, {}, observer);
    if (!result.ok()) {
      // A planner may refuse a problem it cannot represent, but only with a clear precondition.
      EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition) << result.status();
      table += "  " + info.id + ": refused (" + std::string(result.status().message()) + ")\n";
      continue;
    }

    // OnIteration once per iteration, numbered from 0, best non-increasing.
    ASSERT_EQ(static_cast<int>(observer.stats().size()), result->iterations);
    for (size_t i = 0; i < observer.stats().size(); ++i) {
      EXPECT_EQ(observer.stats()[i].iteration, static_cast<int>(i));
      if (i > 0) {
        EXPECT_LE(observer.stats()[i].best_fitness, observer.stats()[i - 1].best_fitness);
      }
    }
    EXPECT_LE(result->iterations, kIterations);

    const Path& path = result->raw_path;
    const bool must_succeed =
        !spec.benchmark_file.empty() && map->kind() != MapKind::kTerrain && SeededByDefault(info);
    if (must_succeed) {
      EXPECT_TRUE(result->found) << "a seeded planner must find a path on a real map";
    }
    if (!result->found) {
      EXPECT_TRUE(path.empty()) << "a planner that found nothing returns no path";
      table += "  " + info.id + ": no path\n";
    } else {
      ++succeeded;
      ASSERT_GE(path.size(), 2u);
      EXPECT_EQ(path.front(), spec.start) << "the path must start exactly at the start";
      EXPECT_EQ(path.back(), spec.goal) << "the path must end exactly at the goal";
      const double clearance = IndependentClearance(*map, path);
      EXPECT_GT(clearance, 0.0) << "the path touches an obstacle or leaves the map";
      EXPECT_GE(clearance, spec.clearance - 1e-9) << "the path comes closer than the clearance";
      const double length = PolylineLength(path);
      // On terrain the lattice optimum minimises the terrain objective, not length, and bounds
      // the continuous optimum from above: no length bound there.
      if (map->kind() != MapKind::kTerrain) {
        EXPECT_GE(length, optimum.length * (1 - 1e-9)) << "shorter than the exact optimum";
      }
      if (must_succeed && spec.clearance == 0.0) {
        EXPECT_LE(length, 1.05 * optimum.length) << "a seeded planner far from the optimum";
      }
      char line[160];
      std::snprintf(line, sizeof line, "  %s: path, %.4f x the optimum, clearance %.3f\n",
                    info.id.c_str(), length / optimum.length, clearance);
      table += line;
    }

    // The same seed gives the same path, bit for bit.
    NullObserver quiet;
    absl::StatusOr<PlanResult> again = RunPlan(DefaultRegistry(), request, {}, quiet);
    ASSERT_TRUE(again.ok()) << again.status();
    EXPECT_EQ(again->raw_path, path) << "the same seed gave another path";

    // A stop token tripped during an iteration ends the search within one more iteration.
    StopToken stop;
    RecordingObserver canceller(stop, kCancelAt);
    absl::StatusOr<PlanResult> stopped = RunPlan(DefaultRegistry(), request, stop, canceller);
    ASSERT_TRUE(stopped.ok()) << stopped.status();
    EXPECT_LE(stopped->iterations, kCancelAt + 2);
    if (result->iterations > kCancelAt + 1) {
      EXPECT_EQ(stopped->stop_reason, StopReason::kCancelled);
    }
  }
  std::printf("[ contract ] %s: %d of %d planners found a path (optimum %.4f by %s)\n%s",
              spec.name.c_str(), succeeded, claimed, optimum.length, optimum.planner.c_str(),
              table.c_str());
}

INSTANTIATE_TEST_SUITE_P(Maps, PlannerContractTest,
                         ::testing::Range(0, static_cast<int>(ContractMaps().size())),
                         [](const ::testing::TestParamInfo<int>& info) {
                           std::string name = ContractMaps()[info.param].name;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace swarmplan
