#include "core/algorithms/afsa/fish_moves.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "core/algorithms/afsa/fish_swarm.h"
#include "core/registry.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan {
namespace {

using namespace swarmplan::testing;
using Variant = FishSwarmParams::Variant;

// Whether the segment a-b meets the closed square [x0, x0 + 1] x [y0, y0 + 1] (Liang-Barsky
// clipping); touching an edge or a corner counts.
bool SegmentMeetsSquare(const Point3& a, const Point3& b, double x0, double y0) {
  double enter = 0.0, leave = 1.0;
  const double d[2] = {b.x() - a.x(), b.y() - a.y()};
  const double p[2] = {a.x(), a.y()};
  const double lo[2] = {x0, y0};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (p[k] < lo[k] || p[k] > lo[k] + 1.0) return false;
      continue;
    }
    double t0 = (lo[k] - p[k]) / d[k], t1 = (lo[k] + 1.0 - p[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave + 1e-12;
}

// Independent of GridMoves: no segment of the path meets a blocked cell's closed square.
void ExpectCollisionFree(const std::vector<std::string>& rows, const Path& path) {
  for (size_t i = 1; i < path.size(); ++i) {
    for (size_t y = 0; y < rows.size(); ++y) {
      for (size_t x = 0; x < rows[y].size(); ++x) {
        if (rows[y][x] != '#') continue;
        EXPECT_FALSE(SegmentMeetsSquare(path[i - 1], path[i], static_cast<double>(x),
                                        static_cast<double>(y)))
            << "segment " << i << " meets cell (" << x << ", " << y << ")";
      }
    }
  }
}

TEST(FishMovesTest, DirectionAimIsEquationThreeToFive) {
  const FishAim aim = DirectionAim(Cell{1, 2}, Cell{4, 6}, 2.5);  // unit direction (0.6, 0.8)
  EXPECT_DOUBLE_EQ(aim.x, 1.0 + 2.5 * 0.6);
  EXPECT_DOUBLE_EQ(aim.y, 2.0 + 2.5 * 0.8);
  const FishAim still = DirectionAim(Cell{3, 3}, Cell{3, 3}, 2.0);
  EXPECT_DOUBLE_EQ(still.x, 3.0);
  EXPECT_DOUBLE_EQ(still.y, 3.0);
}

TEST(FishMovesTest, DirectionMoveOnAnEmptyGridLandsOnTheCellTheEquationGives) {
  const OccupancyGrid grid = GridFromRows(std::vector<std::string>(11, std::string(11, '.')));
  GridMoves moves(grid, MoveRules{Neighbourhood::k24, true, 0.0});
  const Cell from{5, 5}, target{9, 8};  // unit direction (0.8, 0.6)
  const std::vector<Cell>& valid = moves.ValidMoves(from);
  // Step 2√2: the aim (7.263, 6.697) is nearest to (7, 7) (squared distance 0.161; (7, 6) 0.555).
  EXPECT_EQ(DirectionMove(from, target, 2.0 * std::sqrt(2.0), valid), (Cell{7, 7}));
  // Step 1: the aim (5.8, 5.6) is nearest to (6, 6) (0.2; (6, 5) 0.4).
  EXPECT_EQ(DirectionMove(from, target, 1.0, valid), (Cell{6, 6}));
  // Step 2 straight along an axis: (7, 5) exactly.
  EXPECT_EQ(DirectionMove(from, Cell{10, 5}, 2.0, valid), (Cell{7, 5}));
  // A target one cell away and a long step: the target itself, the only move closer to it.
  EXPECT_EQ(DirectionMove(from, Cell{5, 4}, 2.0 * std::sqrt(2.0), valid), (Cell{5, 4}));
}

TEST(FishMovesTest, DirectionMoveSkipsBlockedCellsAndNeverGoesFarther) {
  // (7, 7) blocked: the aim (7.263, 6.697) falls back to the nearest valid move, (7, 6).
  std::vector<std::string> rows(11, std::string(11, '.'));
  rows[7][7] = '#';
  const OccupancyGrid grid = GridFromRows(rows);
  GridMoves moves(grid, MoveRules{Neighbourhood::k24, true, 0.0});
  EXPECT_EQ(DirectionMove(Cell{5, 5}, Cell{9, 8}, 2.0 * std::sqrt(2.0), moves.ValidMoves({5, 5})),
            (Cell{7, 6}));
  // Only moves away from the target: none is taken.
  EXPECT_EQ(DirectionMove(Cell{5, 5}, Cell{9, 5}, 2.0, {Cell{4, 5}, Cell{5, 4}, Cell{5, 6}}),
            std::nullopt);
  // A step beyond the target: (2, 0) is nearest to the aim but not closer to the target.
  EXPECT_EQ(DirectionMove(Cell{0, 0}, Cell{1, 0}, 2.0, {Cell{2, 0}, Cell{1, 0}}), (Cell{1, 0}));
}

// The fish at (0, 0) sees 13 cells within visual 2: itself, 4 at distance 1, 4 at √2, 4 at 2.
constexpr int kCellsInViewOfTwo = 12;  // without the fish's own

TEST(FishMovesTest, CullingTriesEachCellInViewOnce) {
  std::map<std::pair<int, int>, int> tried;
  const auto usable = [](Cell) { return true; };
  const auto food = [&tried](Cell c) {
    ++tried[{c.x, c.y}];
    return 100.0;  // never better: every try fails
  };
  Rng rng(3);
  EXPECT_EQ(PreyTarget(Cell{0, 0}, 1.0, PreySearch{100, 2.0, true}, usable, food, rng),
            std::nullopt);
  EXPECT_EQ(static_cast<int>(tried.size()), kCellsInViewOfTwo);
  for (const auto& [cell, count] : tried) {
    EXPECT_EQ(count, 1) << cell.first << "," << cell.second;
    EXPECT_LE(std::hypot(cell.first, cell.second), 2.0);
    EXPECT_FALSE(cell.first == 0 && cell.second == 0);
  }
  // Without culling the same 100 tries evaluate cells again.
  tried.clear();
  Rng again(3);
  PreyTarget(Cell{0, 0}, 1.0, PreySearch{100, 2.0, false}, usable, food, again);
  int evaluations = 0;
  for (const auto& [cell, count] : tried) evaluations += count;
  EXPECT_GT(evaluations, static_cast<int>(tried.size()));
}

TEST(FishMovesTest, CullingSpendsNoTryOnUnusableCells) {
  // One usable cell in view, and it is better: with culling one try always finds it; without,
  // a single draw hits it with probability 1/25.
  const Cell only{1, 1};
  const auto usable = [only](Cell c) { return c == only; };
  const auto food = [](Cell c) { return FishDistance(c, Cell{10, 10}); };
  const double here = FishDistance(Cell{0, 0}, Cell{10, 10});
  int culled_found = 0, plain_found = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    Rng a(seed), b(seed);
    culled_found +=
        PreyTarget(Cell{0, 0}, here, PreySearch{1, 2.0, true}, usable, food, a) == only ? 1 : 0;
    plain_found +=
        PreyTarget(Cell{0, 0}, here, PreySearch{1, 2.0, false}, usable, food, b) == only ? 1 : 0;
  }
  EXPECT_EQ(culled_found, 20);
  EXPECT_LT(plain_found, 20);
}

TEST(FishMovesTest, PreyReturnsOnlyBetterCellsInView) {
  const auto usable = [](Cell c) { return c.x >= 0 && c.y >= 0; };
  const Cell goal{6, 0};
  const auto food = [goal](Cell c) { return FishDistance(c, goal); };
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    for (bool culling : {false, true}) {
      Rng rng(seed);
      const std::optional<Cell> c =
          PreyTarget(Cell{3, 3}, food(Cell{3, 3}), PreySearch{8, 2.5, culling}, usable, food, rng);
      if (!c) continue;
      EXPECT_LE(FishDistance(*c, Cell{3, 3}), 2.5);
      EXPECT_LT(food(*c), food(Cell{3, 3}));
      EXPECT_TRUE(usable(*c));
    }
  }
}

FishSwarmParams WithMove(Variant variant, FishSwarmParams::Move move) {
  FishSwarmParams p = FishSwarmParams::Defaults(variant);
  p.move = move;
  return p;
}

SearchResult Solve(const FishSwarmParams& params, const Problem& problem) {
  FishSwarmPlanner planner{params};
  NullObserver none;
  absl::StatusOr<SearchResult> r = planner.Solve(problem, StopToken(), none);
  EXPECT_TRUE(r.ok()) << r.status();
  return r.ok() ? *r : SearchResult{};
}

TEST(FishMovesTest, PaperMovesGiveValidPathsFromStartToGoal) {
  const std::vector<std::string> rows = FishSmallRows();
  const MapPtr map = GridMap(rows);
  int found = 0;
  for (Variant variant : {Variant::kDafsa, Variant::kIdafsa}) {
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{9, 9}, seed);
      const SearchResult r = Solve(FishSwarmParams::Defaults(variant), problem);
      if (!r.found) continue;
      ++found;
      EXPECT_EQ(r.path.front(), problem.start);
      EXPECT_EQ(r.path.back(), problem.goal);
      ExpectCollisionFree(rows, r.path);
    }
  }
  EXPECT_GT(found, 0);
}

TEST(FishMovesTest, SameSeedSamePathWithEitherMove) {
  const MapPtr map = GridMap(FishSmallRows());
  const Problem problem = GridProblemFor(map, Cell{0, 9}, Cell{9, 0}, 42);
  for (FishSwarmParams::Move move :
       {FishSwarmParams::Move::kDirection, FishSwarmParams::Move::kRandomCloser}) {
    for (Variant variant : {Variant::kAfsa, Variant::kDafsa, Variant::kIdafsa}) {
      const FishSwarmParams params = WithMove(variant, move);
      const SearchResult a = Solve(params, problem);
      const SearchResult b = Solve(params, problem);
      EXPECT_EQ(a.path, b.path);
      EXPECT_EQ(a.evaluations, b.evaluations);
    }
  }
}

TEST(FishMovesTest, TheMoveChangesTheSearch) {
  const MapPtr map = GridMap(FishSmallRows());
  const Problem problem = GridProblemFor(map, Cell{0, 0}, Cell{9, 9}, 5);
  const SearchResult direction =
      Solve(WithMove(Variant::kIdafsa, FishSwarmParams::Move::kDirection), problem);
  const SearchResult closer =
      Solve(WithMove(Variant::kIdafsa, FishSwarmParams::Move::kRandomCloser), problem);
  EXPECT_NE(direction.evaluations, closer.evaluations);
}

TEST(FishMovesTest, ParametersAndTheirDefaults) {
  Registry registry;
  ASSERT_TRUE(registry.Register(AfsaInfo()).ok());
  ASSERT_TRUE(registry.Register(IdafsaInfo()).ok());
  EXPECT_TRUE(registry.Create("idafsa", {{"move", std::string("random-closer")}}).ok());
  EXPECT_FALSE(registry.Create("idafsa", {{"move", std::string("sideways")}}).ok());
  EXPECT_TRUE(registry.Create("afsa", {{"prey_culling", true}}).ok());
  EXPECT_EQ(FishSwarmParams::Defaults(Variant::kIdafsa).move, FishSwarmParams::Move::kDirection);
  EXPECT_TRUE(FishSwarmParams::Defaults(Variant::kIdafsa).prey_culling);
  EXPECT_TRUE(FishSwarmParams::Defaults(Variant::kDafsa).prey_culling);
  EXPECT_FALSE(FishSwarmParams::Defaults(Variant::kAfsa).prey_culling);
}

}  // namespace
}  // namespace swarmplan
