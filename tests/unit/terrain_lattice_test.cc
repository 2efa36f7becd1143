// terrain-lattice: the exact optimum of the terrain objective on the voxel lattice, checked
// against a brute-force Dijkstra written here, against a known optimum, and against the terrain
// planners where the comparison holds.

#include "core/algorithms/exact/terrain_lattice.h"

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/terrain_collision.h"
#include "core/operators/terrain_path_cost.h"
#include "core/planner.h"
#include "core/random.h"
#include "core/registry.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

// Bilinear ground from the heights, written apart from Terrain (NaN outside the centres).
double Ground(const std::vector<double>& h, int width, int depth, double cell, const Point2& origin,
              double x, double y) {
  const double fx = (x - origin.x()) / cell - 0.5, fy = (y - origin.y()) / cell - 0.5;
  if (fx < -1e-12 || fy < -1e-12 || fx > width - 1 + 1e-12 || fy > depth - 1 + 1e-12) {
    return std::nan("");
  }
  const int i = std::clamp(static_cast<int>(std::floor(fx)), 0, width - 2);
  const int j = std::clamp(static_cast<int>(std::floor(fy)), 0, depth - 2);
  const double u = fx - i, v = fy - j;
  const auto at = [&](int a, int b) { return h[b * width + a]; };
  return (1 - u) * (1 - v) * at(i, j) + u * (1 - v) * at(i + 1, j) + (1 - u) * v * at(i, j + 1) +
         u * v * at(i + 1, j + 1);
}

// Every point of the path, sampled densely, keeps the clearance (less a rounding margin).
void ExpectCollisionFree(const Path& path, const std::vector<double>& h, int width, int depth,
                         double cell, const Point2& origin, double clearance, double ceiling) {
  for (size_t s = 0; s + 1 < path.size(); ++s) {
    for (int k = 0; k <= 400; ++k) {
      const Point3 p = path[s] + (path[s + 1] - path[s]) * (k / 400.0);
      const double g = Ground(h, width, depth, cell, origin, p.x(), p.y());
      ASSERT_FALSE(std::isnan(g)) << "segment " << s << " leaves the map";
      EXPECT_GE(p.z() - g, clearance - 1e-9) << "segment " << s << " sample " << k;
      EXPECT_LE(p.z(), ceiling + 1e-9);
    }
  }
}

// Brute force over the lattice as the planner's documentation defines it: every node, every
// 26-neighbour pair, every start and goal join, then Dijkstra by scanning all nodes.
double BruteForceOptimum(const Terrain& terrain, const Point3& start, const Point3& goal,
                         double clearance, double step) {
  const TerrainCollisionChecker checker(terrain);
  const double base = terrain.min_height() + clearance;
  const int levels = static_cast<int>(std::floor((terrain.ceiling() - base) / step + 1e-9)) + 1;
  struct Node {
    int i, j, k;
    Point3 p;
  };
  std::vector<Node> nodes;
  nodes.push_back({-1, -1, -1, start});
  nodes.push_back({-1, -1, -1, goal});
  for (int j = 0; j < terrain.depth(); ++j) {
    for (int i = 0; i < terrain.width(); ++i) {
      for (int k = 0; k < levels; ++k) {
        const Point2 xy = terrain.CellCentre(i, j);
        const Point3 p(xy.x(), xy.y(), base + k * step);
        if (checker.Clearance(p) >= clearance) nodes.push_back({i, j, k, p});
      }
    }
  }
  const auto near = [&](const Node& n, const Point3& q) {
    const Point2 c = terrain.ToCell(q.head<2>());
    return std::abs(n.i - c.x()) <= 1 && std::abs(n.j - c.y()) <= 1 &&
           std::abs(n.p.z() - q.z()) <= step;
  };
  const auto adjacent = [&](size_t a, size_t b) {
    if (a == b || b == 0) return false;  // nothing enters the start
    if (a == 1) return false;            // nothing leaves the goal
    if (a == 0 && b == 1) return true;
    if (a == 0) return near(nodes[b], start);
    if (b == 1) return near(nodes[a], goal);
    return std::abs(nodes[a].i - nodes[b].i) <= 1 && std::abs(nodes[a].j - nodes[b].j) <= 1 &&
           std::abs(nodes[a].k - nodes[b].k) <= 1;
  };
  std::vector<double> dist(nodes.size(), kInf);
  std::vector<bool> done(nodes.size(), false);
  dist[0] = 0.0;
  for (;;) {
    size_t u = nodes.size();
    for (size_t n = 0; n < nodes.size(); ++n) {
      if (!done[n] && dist[n] < kInf && (u == nodes.size() || dist[n] < dist[u])) u = n;
    }
    if (u == nodes.size()) break;
    done[u] = true;
    for (size_t v = 0; v < nodes.size(); ++v) {
      if (done[v] || !adjacent(u, v)) continue;
      if (!checker.SegmentFree(nodes[u].p, nodes[v].p, clearance)) continue;
      dist[v] = std::min(dist[v],
                         dist[u] + TerrainSegmentCost(nodes[u].p, nodes[v].p, terrain.cell_size()));
    }
  }
  return dist[1];
}

TEST(TerrainLatticeTest, MatchesBruteForceOnSmallRandomTerrains) {
  Rng rng(41);
  const int width = 5, depth = 4;
  const double cell = 2.0, clearance = 0.3, step = 1.0, ceiling = 6.0;
  const Point2 origin(5, -3);
  int found = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<double> h(width * depth);
    for (double& v : h) v = rng.Uniform(0.0, 3.5);
    const Terrain terrain = *Terrain::Create(width, depth, h, cell, origin, ceiling);
    // A point up to 0.4 cells from the centre of cell (i, j), towards the inside (x: by `dx`).
    const auto endpoint = [&](int i, int j, double dx) {
      const Point2 xy =
          terrain.ToWorld(Point2(i + dx * rng.Uniform(0, 0.4), j + rng.Uniform(0, 0.4)));
      return Point3(xy.x(), xy.y(), terrain.GroundAt(xy) + clearance + rng.Uniform(0.0, 1.5));
    };
    const Point3 start = endpoint(0, rng.Uniform() < 0.5 ? 0 : 2, 1.0);
    const Point3 goal = endpoint(width - 1, rng.Uniform() < 0.5 ? 1 : 2, -1.0);
    TerrainLatticeOptions options;
    options.vertical_step = step;
    absl::StatusOr<TerrainLatticeResult> lattice =
        TerrainLatticeOptimum(terrain, start, goal, clearance, options);
    ASSERT_TRUE(lattice.ok()) << lattice.status();
    EXPECT_EQ(lattice->levels.base, terrain.min_height() + clearance);
    EXPECT_EQ(lattice->levels.step, step);
    const double brute = BruteForceOptimum(terrain, start, goal, clearance, step);
    if (brute == kInf) {
      EXPECT_TRUE(lattice->path.empty()) << "trial " << trial;
      continue;
    }
    ++found;
    ASSERT_FALSE(lattice->path.empty()) << "trial " << trial;
    EXPECT_NEAR(lattice->cost, brute, 1e-9) << "trial " << trial;
    EXPECT_EQ(lattice->path.front(), start);
    EXPECT_EQ(lattice->path.back(), goal);
    EXPECT_NEAR(TerrainPathCost(lattice->path, cell), lattice->cost, 1e-12);
    ExpectCollisionFree(lattice->path, h, width, depth, cell, origin, clearance, ceiling);
  }
  EXPECT_GE(found, 6);  // most trials have a path: the comparison is not vacuous
}

const Registry& TerrainRegistry() { return DefaultRegistry(); }

class CountingObserver final : public Observer {
 public:
  void OnIteration(const IterationStats&) override { ++calls; }
  int calls = 0;
};

// A plateau 10 high with a straight channel of ground 0 along row 2; cells of `cell` units.
// Start and goal in the channel at clearance height, on the first and last column.
Problem ChannelProblem(double cell) {
  const int width = 10, depth = 5;
  std::vector<double> h(width * depth, 10.0);
  for (int i = 0; i < width; ++i) h[2 * width + i] = 0.0;
  Problem problem;
  problem.map = std::make_shared<Map>(*Terrain::Create(width, depth, h, cell, {0, 0}, 20.0));
  problem.clearance = 0.5;
  const Terrain& terrain = *problem.map->terrain();
  const Point2 s = terrain.CellCentre(0, 2), g = terrain.CellCentre(width - 1, 2);
  problem.start = Point3(s.x(), s.y(), 0.5);
  problem.goal = Point3(g.x(), g.y(), 0.5);
  problem.seed = 3;
  return problem;
}

// Every segment ends at least 0.5 high, so any path costs at least (1 + 0.5 / cell) times its
// x-extent, 9 cells: the straight path along the channel floor, on the lattice, reaches it.
double ChannelOptimum(double cell) { return 9 * cell * (1.0 + 0.5 / cell); }

TEST(TerrainLatticePlannerTest, FindsTheKnownOptimumInWorldUnitsInOneIteration) {
  const Registry& registry = TerrainRegistry();
  for (const double cell : {1.0, 10.0}) {
    const Problem problem = ChannelProblem(cell);
    absl::StatusOr<std::unique_ptr<Planner>> planner = registry.Create("terrain-lattice", {});
    ASSERT_TRUE(planner.ok()) << planner.status();
    CountingObserver observer;
    absl::StatusOr<SearchResult> result = (*planner)->Solve(problem, StopToken(), observer);
    ASSERT_TRUE(result.ok()) << result.status();
    ASSERT_TRUE(result->found);
    EXPECT_NEAR(result->fitness, ChannelOptimum(cell), 1e-9) << "cell " << cell;
    EXPECT_EQ(result->iterations, 1);
    EXPECT_EQ(observer.calls, 1);
    EXPECT_EQ(result->path.front(), problem.start);
    EXPECT_EQ(result->path.back(), problem.goal);
    for (const Point3& p : result->path) EXPECT_EQ(p.z(), 0.5);
    CountingObserver again;
    absl::StatusOr<SearchResult> second = (*planner)->Solve(problem, StopToken(), again);
    ASSERT_TRUE(second.ok());
    EXPECT_EQ(second->path, result->path);
  }
}

// The lattice optimum bounds the continuous optimum from above only, so a continuous path may
// beat it in general. In the channel the continuous optimum lies on the lattice (see
// ChannelOptimum), so there no terrain planner's path may cost less.
TEST(TerrainLatticePlannerTest, NoTerrainPlannerBeatsItWhereItIsTheContinuousOptimum) {
  const Registry& registry = TerrainRegistry();
  const Problem problem = ChannelProblem(2.0);
  absl::StatusOr<std::unique_ptr<Planner>> lattice = registry.Create("terrain-lattice", {});
  ASSERT_TRUE(lattice.ok());
  NullObserver observer;
  const double optimum = (*lattice)->Solve(problem, StopToken(), observer)->fitness;
  ASSERT_NEAR(optimum, ChannelOptimum(2.0), 1e-9);
  for (const std::string id : {"bas", "lfs-bas", "aco-bas", "sio-bas", "multi-bas", "aco"}) {
    absl::StatusOr<std::unique_ptr<Planner>> planner =
        registry.Create(id, {{"iterations", int64_t{60}}});
    ASSERT_TRUE(planner.ok()) << id << ": " << planner.status();
    absl::StatusOr<SearchResult> result = (*planner)->Solve(problem, StopToken(), observer);
    ASSERT_TRUE(result.ok()) << id << ": " << result.status();
    if (!result->found) continue;
    EXPECT_GE(TerrainPathCost(result->path, 2.0), optimum - 1e-9) << id;
    EXPECT_GE(result->fitness, optimum - 1e-9) << id;
  }
}

TEST(TerrainLatticePlannerTest, RefusesWhatItCannotSearch) {
  const Problem problem = ChannelProblem(1.0);
  TerrainLatticeOptions fine;
  fine.vertical_step = 1e-6;
  absl::StatusOr<TerrainLatticeResult> huge = TerrainLatticeOptimum(
      *problem.map->terrain(), problem.start, problem.goal, problem.clearance, fine);
  EXPECT_EQ(huge.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(huge.status().message(), ::testing::HasSubstr("vertical_step"));

  // Ground 5 below zero with cells of 1: a height term of -5 per cell would pay for travel.
  const Terrain deep = *Terrain::Create(3, 3, std::vector<double>(9, -5.0), 1.0, {0, 0}, 0.0);
  absl::StatusOr<TerrainLatticeResult> negative = TerrainLatticeOptimum(
      deep, Point3(0.5, 0.5, -4), Point3(2.5, 0.5, -4), 0.5, TerrainLatticeOptions{});
  EXPECT_EQ(negative.status().code(), absl::StatusCode::kFailedPrecondition);

  absl::StatusOr<TerrainLatticeResult> outside =
      TerrainLatticeOptimum(*problem.map->terrain(), Point3(1e300, 2.5, 1), problem.goal,
                            problem.clearance, TerrainLatticeOptions{});
  EXPECT_EQ(outside.status().code(), absl::StatusCode::kInvalidArgument);

  const Registry& registry = TerrainRegistry();
  Problem grid = problem;
  grid.map = std::make_shared<Map>(*OccupancyGrid::Create(4, 4, std::vector<int8_t>(16, 0)));
  NullObserver observer;
  absl::StatusOr<SearchResult> wrong =
      (*registry.Create("terrain-lattice", {}))->Solve(grid, StopToken(), observer);
  EXPECT_EQ(wrong.status().code(), absl::StatusCode::kFailedPrecondition);

  StopToken stop;
  stop.Cancel();
  absl::StatusOr<SearchResult> cancelled =
      (*registry.Create("terrain-lattice", {}))->Solve(problem, stop, observer);
  ASSERT_TRUE(cancelled.ok());
  EXPECT_FALSE(cancelled->found);
  EXPECT_EQ(cancelled->stop_reason, StopReason::kCancelled);
}

}  // namespace
}  // namespace swarmplan
