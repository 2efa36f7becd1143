#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/geometry/collision.h"
#include "core/map/map.h"
#include "core/registry.h"
#include "core/run.h"
#include "gtest/gtest.h"
#include "tests/unit/plan_test_support.h"

namespace swarmplan {
namespace {

// --- Brute force, independent of the planner: Dijkstra over the visibility graph of every
// lattice point that touches a blocked cell, plus start and goal, in grid coordinates. A
// segment is allowed when it stays in the map, meets no open blocked square, runs along no
// edge between two blocked cells (outside counts as blocked) and passes through no lattice
// point where two blocked cells touch only diagonally. Its infimum is the optimum the planner
// approaches from the free side.
class BruteForce {
 public:
  BruteForce(int width, int height, std::vector<uint8_t> blocked)
      : w_(width), h_(height), blocked_(std::move(blocked)) {}

  bool Blocked(int x, int y) const {
    return x < 0 || y < 0 || x >= w_ || y >= h_ || blocked_[static_cast<size_t>(y) * w_ + x];
  }
  bool DiagonalPinch(int x, int y) const {
    const bool a = Blocked(x - 1, y - 1), b = Blocked(x, y - 1);
    const bool c = Blocked(x - 1, y), d = Blocked(x, y);
    return (a && d && !b && !c) || (b && c && !a && !d);
  }

  bool SegmentAllowed(const Point2& u, const Point2& v) const {
    const Point2 d = v - u;
    const double len = d.norm();
    const int x0 = static_cast<int>(std::floor(std::min(u.x(), v.x()))) - 1;
    const int x1 = static_cast<int>(std::ceil(std::max(u.x(), v.x()))) + 1;
    const int y0 = static_cast<int>(std::floor(std::min(u.y(), v.y()))) - 1;
    const int y1 = static_cast<int>(std::ceil(std::max(u.y(), v.y()))) + 1;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (Blocked(x, y) && x >= 0 && y >= 0 && x < w_ && y < h_ &&
            MeetsOpenSquare(u, d, len, x, y)) {
          return false;
        }
      }
    }
    // Edges between two blocked cells, along the segment's line.
    constexpr double kEps = 1e-9;
    if (std::abs(d.y()) < kEps && std::abs(u.y() - std::round(u.y())) < kEps) {
      const int row = static_cast<int>(std::round(u.y()));
      for (int x = x0; x <= x1; ++x) {
        const double overlap = std::min<double>(x + 1, std::max(u.x(), v.x())) -
                               std::max<double>(x, std::min(u.x(), v.x()));
        if (overlap > kEps && Blocked(x, row - 1) && Blocked(x, row)) return false;
      }
    }
    if (std::abs(d.x()) < kEps && std::abs(u.x() - std::round(u.x())) < kEps) {
      const int col = static_cast<int>(std::round(u.x()));
      for (int y = y0; y <= y1; ++y) {
        const double overlap = std::min<double>(y + 1, std::max(u.y(), v.y())) -
                               std::max<double>(y, std::min(u.y(), v.y()));
        if (overlap > kEps && Blocked(col - 1, y) && Blocked(col, y)) return false;
      }
    }
    for (int y = std::max(y0, 0); y <= std::min(y1, h_); ++y) {
      for (int x = std::max(x0, 0); x <= std::min(x1, w_); ++x) {
        if (!DiagonalPinch(x, y)) continue;
        const Point2 p(x, y);
        const double t = (p - u).dot(d) / (len * len);
        if (t > kEps && t < 1 - kEps && (u + t * d - p).norm() < kEps) return false;
      }
    }
    return true;
  }

  double ShortestPath(const Point2& start, const Point2& goal) const {
    std::vector<Point2> nodes = {start, goal};
    for (int y = 0; y <= h_; ++y) {
      for (int x = 0; x <= w_; ++x) {
        const int count =
            Blocked(x - 1, y - 1) + Blocked(x, y - 1) + Blocked(x - 1, y) + Blocked(x, y);
        if (count > 0 && count < 4 && !DiagonalPinch(x, y)) nodes.emplace_back(x, y);
      }
    }
    const size_t n = nodes.size();
    std::vector<double> dist(n, kInf);
    std::vector<char> done(n, 0);
    dist[0] = 0;
    for (size_t iter = 0; iter < n; ++iter) {
      size_t best = n;
      for (size_t i = 0; i < n; ++i) {
        if (!done[i] && dist[i] < kInf && (best == n || dist[i] < dist[best])) best = i;
      }
      if (best == n) break;
      if (best == 1) return dist[1];
      done[best] = 1;
      for (size_t i = 0; i < n; ++i) {
        if (done[i]) continue;
        const double nd = dist[best] + (nodes[i] - nodes[best]).norm();
        if (nd < dist[i] && SegmentAllowed(nodes[best], nodes[i])) dist[i] = nd;
      }
    }
    return dist[1];
  }

 private:
  // Whether the segment u + t d, t in [0, 1], has a stretch longer than 1e-9 inside the open
  // square of cell (x, y).
  static bool MeetsOpenSquare(const Point2& u, const Point2& d, double len, int x, int y) {
    double lo = 0.0, hi = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
      const double a = axis == 0 ? x : y;
      if (d[axis] == 0.0) {
        if (!(u[axis] > a && u[axis] < a + 1)) return false;
        continue;
      }
      double t1 = (a - u[axis]) / d[axis], t2 = (a + 1 - u[axis]) / d[axis];
      if (t1 > t2) std::swap(t1, t2);
      lo = std::max(lo, t1);
      hi = std::min(hi, t2);
    }
    return (hi - lo) * len > 1e-9;
  }

  int w_, h_;
  std::vector<uint8_t> blocked_;
};

struct RandomGrid {
  MapPtr map;
  std::vector<uint8_t> blocked;
  int width, height;
  double resolution;
  Point2 origin;
};

RandomGrid MakeRandomGrid(std::mt19937_64& rng, double density, double resolution,
                          const Point2& origin) {
  RandomGrid g;
  g.width = std::uniform_int_distribution<int>(8, 14)(rng);
  g.height = std::uniform_int_distribution<int>(8, 14)(rng);
  g.resolution = resolution;
  g.origin = origin;
  std::bernoulli_distribution block(density);
  std::vector<int8_t> cells(static_cast<size_t>(g.width) * g.height);
  g.blocked.resize(cells.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    g.blocked[i] = block(rng);
    cells[i] = g.blocked[i] ? OccupancyGrid::kOccupied : OccupancyGrid::kFree;
  }
  absl::StatusOr<OccupancyGrid> grid =
      OccupancyGrid::Create(g.width, g.height, std::move(cells), resolution, origin);
  EXPECT_TRUE(grid.ok()) << grid.status();
  g.map = std::make_shared<const Map>(Map::Data(*std::move(grid)));
  return g;
}

// A random point (grid coordinates) whose closed neighbourhood touches no blocked cell.
bool RandomFreePoint(std::mt19937_64& rng, const BruteForce& brute, int w, int h, Point2* p) {
  std::uniform_real_distribution<double> ux(0.0, w), uy(0.0, h);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const Point2 q(ux(rng), uy(rng));
    const int cx = static_cast<int>(q.x()), cy = static_cast<int>(q.y());
    bool touches = false;
    for (int y = cy - 1; y <= cy + 1; ++y) {
      for (int x = cx - 1; x <= cx + 1; ++x) {
        if (!brute.Blocked(x, y) || x < 0 || y < 0 || x >= w || y >= h) continue;
        const double dx = std::max({0.0, x - q.x(), q.x() - (x + 1)});
        const double dy = std::max({0.0, y - q.y(), q.y() - (y + 1)});
        if (std::hypot(dx, dy) < 1e-6) touches = true;
      }
    }
    if (!touches) {
      *p = q;
      return true;
    }
  }
  return false;
}

using ::swarmplan::testing::NullObserver;

absl::StatusOr<PlanResult> Plan(const std::string& algorithm, const MapPtr& map,
                                const Point2& start, const Point2& goal, double clearance = 0) {
  return ::swarmplan::testing::PlanOnMap(algorithm, map, start, goal, clearance);
}

double Length(const Path& path) {
  double total = 0;
  for (size_t i = 0; i + 1 < path.size(); ++i) total += (path[i + 1] - path[i]).norm();
  return total;
}

TEST(ExactAnyAngleTest, MatchesBruteForceOnRandomGrids) {
  std::mt19937_64 rng(20261201);
  int compared = 0, unreachable = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double density = trial % 3 == 0 ? 0.15 : (trial % 3 == 1 ? 0.3 : 0.42);
    const double resolution = trial % 4 == 0 ? 0.5 : 1.0;
    const Point2 origin = trial % 5 == 0 ? Point2(-3.25, 7.5) : Point2::Zero();
    const RandomGrid g = MakeRandomGrid(rng, density, resolution, origin);
    const BruteForce brute(g.width, g.height, g.blocked);
    Point2 s, t;
    if (!RandomFreePoint(rng, brute, g.width, g.height, &s) ||
        !RandomFreePoint(rng, brute, g.width, g.height, &t)) {
      continue;
    }
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " " << g.width << "x" << g.height
                                      << " from " << s.transpose() << " to " << t.transpose());
    const double optimum = brute.ShortestPath(s, t) * resolution;
    const Point2 ws = origin + s * resolution, wt = origin + t * resolution;
    absl::StatusOr<PlanResult> result = Plan("exact-any-angle", g.map, ws, wt);
    ASSERT_TRUE(result.ok()) << result.status();
    if (optimum == kInf) {
      EXPECT_FALSE(result->found);
      ++unreachable;
      continue;
    }
    ASSERT_TRUE(result->found);
    const Path& path = result->raw_path;
    ASSERT_GE(path.size(), 2u);
    EXPECT_EQ(path.front(), Point3(ws.x(), ws.y(), 0));
    EXPECT_EQ(path.back(), Point3(wt.x(), wt.y(), 0));
    EXPECT_TRUE(MakeCollisionChecker(*g.map)->PathFree(path, 0.0));
    const double length = Length(path);
    EXPECT_GE(length, optimum - 1e-9);
    EXPECT_LE(length, optimum * (1 + 1e-6) + 1e-9) << "brute force " << optimum;
    ++compared;
  }
  EXPECT_GT(compared, 200);
  EXPECT_GT(unreachable, 0);
}

TEST(ExactAnyAngleTest, KeepsTheClearanceOnRandomGrids) {
  std::mt19937_64 rng(7);
  int found = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const RandomGrid g = MakeRandomGrid(rng, 0.08, 1.0, Point2::Zero());
    const double clearance = trial % 2 == 0 ? 0.5 : 1.0;
    const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*g.map);
    // Ends that keep the clearance by more than a cell diagonal lie in free inflated cells.
    std::uniform_real_distribution<double> ux(0.0, g.width), uy(0.0, g.height);
    const auto end_point = [&] {
      Point2 p(ux(rng), uy(rng));
      for (int i = 0; i < 50 && checker->Clearance(Point3(p.x(), p.y(), 0)) < clearance + 1.5;
           ++i) {
        p = Point2(ux(rng), uy(rng));
      }
      return p;
    };
    const Point2 s = end_point(), t = end_point();
    absl::StatusOr<PlanResult> result = Plan("exact-any-angle", g.map, s, t, clearance);
    if (!result.ok()) {
      // Only an endpoint the planning grid cannot use is refused.
      EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
      continue;
    }
    if (!result->found) continue;
    ++found;
    EXPECT_TRUE(checker->PathFree(result->raw_path, clearance)) << "trial " << trial;
    // Never shorter than the optimum without clearance.
    absl::StatusOr<PlanResult> free_plan = Plan("exact-any-angle", g.map, s, t);
    ASSERT_TRUE(free_plan.ok()) << free_plan.status();
    ASSERT_TRUE(free_plan->found);
    EXPECT_GE(Length(result->raw_path), Length(free_plan->raw_path) - 1e-9);
  }
  EXPECT_GT(found, 30);
}

TEST(ExactAnyAngleTest, StraightLineAndWallDetour) {
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(
      5, 3, {0, 0, 0, 0, 0, 0, 0, 100, 0, 0, 0, 0, 0, 0, 0});  // one blocked cell at (2, 1)
  ASSERT_TRUE(grid.ok());
  const MapPtr map = std::make_shared<const Map>(Map::Data(*std::move(grid)));
  absl::StatusOr<PlanResult> straight = Plan("exact-any-angle", map, {0.5, 0.5}, {4.5, 0.5});
  ASSERT_TRUE(straight.ok()) << straight.status();
  ASSERT_TRUE(straight->found);
  EXPECT_NEAR(Length(straight->raw_path), 4.0, 1e-9);
  // Around the block along its bottom edge, through its corners (2, 1) and (3, 1).
  absl::StatusOr<PlanResult> detour = Plan("exact-any-angle", map, {0.5, 1.5}, {4.5, 1.5});
  ASSERT_TRUE(detour.ok()) << detour.status();
  ASSERT_TRUE(detour->found);
  const double expected = 2 * std::hypot(1.5, 0.5) + 1.0;
  EXPECT_NEAR(Length(detour->raw_path), expected, 1e-6);
  EXPECT_TRUE(MakeCollisionChecker(*map)->PathFree(detour->raw_path, 0.0));
}

TEST(ExactAnyAngleTest, BlockedEndpointsAndUnreachableGoal) {
  // Column x = 2 is a wall: the right side cannot be reached.
  std::vector<int8_t> cells(5 * 4, 0);
  for (int y = 0; y < 4; ++y) cells[y * 5 + 2] = 100;
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(5, 4, cells);
  ASSERT_TRUE(grid.ok());
  const MapPtr map = std::make_shared<const Map>(Map::Data(*std::move(grid)));
  absl::StatusOr<PlanResult> blocked = Plan("exact-any-angle", map, {2.5, 1.5}, {0.5, 0.5});
  ASSERT_FALSE(blocked.ok());
  EXPECT_EQ(blocked.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(blocked.status().message().find("start"), std::string::npos);
  absl::StatusOr<PlanResult> touching = Plan("exact-any-angle", map, {0.5, 0.5}, {2.0, 1.5});
  ASSERT_FALSE(touching.ok());
  EXPECT_NE(touching.status().message().find("goal"), std::string::npos);
  absl::StatusOr<PlanResult> outside = Plan("exact-any-angle", map, {0.5, 0.5}, {9.0, 1.5});
  ASSERT_FALSE(outside.ok());
  EXPECT_NE(outside.status().message().find("outside"), std::string::npos);
  absl::StatusOr<PlanResult> unreachable = Plan("exact-any-angle", map, {0.5, 0.5}, {4.5, 3.5});
  ASSERT_TRUE(unreachable.ok()) << unreachable.status();
  EXPECT_FALSE(unreachable->found);
}

TEST(ExactAnyAngleTest, NeverSqueezesBetweenDiagonalBlocks) {
  // Blocked (1, 0) and (0, 1) touch at (1, 1): from (0.5, 0.5) the only way out is none.
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(3, 3, {0, 100, 0, 100, 0, 0, 0, 0, 0});
  ASSERT_TRUE(grid.ok());
  const MapPtr map = std::make_shared<const Map>(Map::Data(*std::move(grid)));
  absl::StatusOr<PlanResult> result = Plan("exact-any-angle", map, {0.5, 0.5}, {2.5, 2.5});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->found);
}

TEST(ExactAnyAngleTest, StopTokenEndsTheSearch) {
  std::mt19937_64 rng(3);
  const RandomGrid g = MakeRandomGrid(rng, 0.1, 1.0, Point2::Zero());
  PlanRequest request;
  request.algorithm = "exact-any-angle";
  request.problem.map = g.map;
  StopToken stop;
  stop.Cancel();
  NullObserver observer;
  absl::StatusOr<PlanResult> result = RunPlan(DefaultRegistry(), request, stop, observer);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_FALSE(result->found);
  EXPECT_EQ(result->stop_reason, StopReason::kCancelled);
}

}  // namespace
}  // namespace swarmplan
