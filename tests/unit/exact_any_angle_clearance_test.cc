// exact-any-angle with a clearance: the optimum lies between the lower bound (bound=lower) and
// the path returned (bound=upper, the default), checked against a closed form, theta-star and
// the sub-cell grids' own definitions.
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/statusor.h"
#include "core/algorithms/exact/any_angle_grid.h"
#include "core/geometry/collision.h"
#include "core/map/map.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"
#include "tests/unit/plan_test_support.h"

namespace swarmplan {
namespace {

const ParamValues kLowerBound = {{"bound", std::string("lower")}};

MapPtr GridMap(int width, int height, const std::vector<Cell>& blocked) {
  std::vector<int8_t> cells(static_cast<size_t>(width) * height, OccupancyGrid::kFree);
  for (const Cell& c : blocked) cells[static_cast<size_t>(c.y) * width + c.x] = 100;
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(width, height, std::move(cells));
  return std::make_shared<const Map>(Map::Data(*std::move(grid)));
}

// Cells of a size x size grid blocked with `probability`, but for the 3 x 3 corners at (0, 0)
// and (size - 1, size - 1), where the tests start and end.
std::vector<Cell> RandomBlockedCells(std::mt19937_64& rng, int size, double probability) {
  std::bernoulli_distribution blocked(probability);
  std::vector<Cell> cells;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (blocked(rng) && (x > 2 || y > 2) && (x < size - 3 || y < size - 3)) {
        cells.push_back({x, y});
      }
    }
  }
  return cells;
}

double PlannedLength(const MapPtr& map, const std::string& algorithm, const Point2& start,
                     const Point2& goal, double clearance, const ParamValues& params = {}) {
  absl::StatusOr<PlanResult> result =
      ::swarmplan::testing::PlanOnMap(algorithm, map, start, goal, clearance, params);
  if (!result.ok() || !result->found) return -1.0;
  return PathLength(result->raw_path);
}

// Around one blocked square at clearance r the optimum is known: a tangent to the disc of radius
// r around the near top corner, an arc to the top, the square's width, and the mirror image.
TEST(ExactAnyAngleClearanceTest, MatchesTheClosedFormAroundOneSquare) {
  const MapPtr map = GridMap(21, 21, {{10, 10}});
  const Point2 start(5.5, 10.5), goal(15.5, 10.5);
  for (const double r : {0.5, 1.0, 2.25}) {
    SCOPED_TRACE(r);
    const Point2 corner(10.0, 11.0);
    const double d = (start - corner).norm();
    const double toward_start = std::atan2(start.y() - corner.y(), start.x() - corner.x());
    const double tangent_angle = toward_start + 2 * std::numbers::pi - std::acos(r / d);
    const double arc = tangent_angle - std::numbers::pi / 2;
    const double exact = 2 * (std::sqrt(d * d - r * r) + r * arc) + 1.0;
    absl::StatusOr<PlanResult> upper =
        ::swarmplan::testing::PlanOnMap("exact-any-angle", map, start, goal, r);
    ASSERT_TRUE(upper.ok()) << upper.status();
    ASSERT_TRUE(upper->found);
    EXPECT_TRUE(MakeCollisionChecker(*map)->PathFree(upper->raw_path, r));
    const double lower = PlannedLength(map, "exact-any-angle", start, goal, r, kLowerBound);
    EXPECT_LE(lower, exact);
    EXPECT_GE(PathLength(upper->raw_path), exact);
    EXPECT_LE(PathLength(upper->raw_path), exact * (1 + 1e-3));
  }
}

// Every point of a free sub-cell of the upper grid keeps the clearance; every point of a blocked
// sub-cell of the lower grid (outside the map's blocked cells) comes closer than it. Checked on a
// 5 x 5 lattice of points per sub-cell with the map's exact checker.
TEST(ExactAnyAngleClearanceTest, SubCellGridsKeepTheirDefinitions) {
  std::mt19937_64 rng(11);
  std::bernoulli_distribution blocked(0.12);
  std::vector<Cell> cells;
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 12; ++x) {
      if (blocked(rng)) cells.push_back({x, y});
    }
  }
  const MapPtr map = GridMap(12, 12, cells);
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*map);
  for (const double r : {0.3, 0.5, 1.2}) {
    SCOPED_TRACE(r);
    const OccupancyGrid upper = ClearanceGrid(*map->grid(), r, ClearanceBound::kUpper);
    const OccupancyGrid lower = ClearanceGrid(*map->grid(), r, ClearanceBound::kLower);
    ASSERT_EQ(upper.width(), 12 * ClearanceSubdivision(*map->grid()));
    const double h = upper.resolution();
    int free_cells = 0, blocked_cells = 0;
    for (int y = 0; y < upper.height(); ++y) {
      for (int x = 0; x < upper.width(); ++x) {
        const bool inside_obstacle =
            map->grid()->IsBlocked(static_cast<int>(x * h), static_cast<int>(y * h));
        for (int i = 0; i <= 4; ++i) {
          for (int j = 0; j <= 4; ++j) {
            const Point3 p((x + i / 4.0) * h, (y + j / 4.0) * h, 0.0);
            const double kept = checker->Clearance(p);
            if (!upper.IsBlocked(x, y)) {
              EXPECT_GE(kept, r - 1e-12) << x << "," << y;
            }
            if (lower.IsBlocked(x, y) && !inside_obstacle) {
              EXPECT_LT(kept, r) << x << "," << y;
            }
          }
        }
        free_cells += upper.IsBlocked(x, y) ? 0 : 1;
        blocked_cells += lower.IsBlocked(x, y) && !inside_obstacle ? 1 : 0;
      }
    }
    EXPECT_GT(free_cells, 0);
    // Below about half a sub-cell diagonal the lower grid blocks only the obstacles' sub-cells.
    if (r >= 0.5) {
      EXPECT_GT(blocked_cells, 0);
    }
  }
}

// Each sub-cell against every blocked square, with distances between boxes in world units: the
// upper grid blocks a sub-cell whose square comes closer than the clearance to a blocked square,
// the lower grid one inside a blocked square or whose centre lies closer than the clearance less
// half a sub-cell diagonal. Grids with clusters (enclosed cells), unknown cells, cells at the
// edges, two resolutions and an origin off zero.
TEST(ExactAnyAngleClearanceTest, SubCellGridsMatchTheirDefinitionsCellByCell) {
  std::mt19937_64 rng(17);
  for (const double resolution : {1.0, 0.5}) {
    const int width = 23, height = 17;
    std::vector<int8_t> cells(static_cast<size_t>(width) * height, OccupancyGrid::kFree);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const bool cluster = x >= 8 && x < 13 && y >= 5 && y < 9;
        const double r = u(rng);
        int8_t& c = cells[static_cast<size_t>(y) * width + x];
        if (cluster || r < 0.08) c = OccupancyGrid::kOccupied;
        if (r > 0.97) c = OccupancyGrid::kUnknown;
      }
    }
    const OccupancyGrid grid =
        *OccupancyGrid::Create(width, height, cells, resolution, Point2(-3.0, 2.0));
    for (const double clearance : {0.1, 0.3, 0.55, 1.2, 2.3}) {
      for (const ClearanceBound bound : {ClearanceBound::kUpper, ClearanceBound::kLower}) {
        SCOPED_TRACE(::testing::Message()
                     << "resolution " << resolution << " clearance " << clearance
                     << (bound == ClearanceBound::kUpper ? " upper" : " lower"));
        const OccupancyGrid sub = ClearanceGrid(grid, clearance, bound);
        const int s = ClearanceSubdivision(grid);
        ASSERT_EQ(sub.width(), width * s);
        ASSERT_EQ(sub.height(), height * s);
        const double h = resolution / s;
        int blocked_near = 0, mismatches = 0;
        for (int sy = 0; sy < sub.height(); ++sy) {
          for (int sx = 0; sx < sub.width(); ++sx) {
            bool expected = false;
            for (int y = 0; y < height && !expected; ++y) {
              for (int x = 0; x < width && !expected; ++x) {
                if (!grid.IsBlocked(x, y)) continue;
                // Gaps between the sub-cell (or its centre) and the blocked square, per axis.
                const auto gap = [](double lo, double hi, double a, double b) {
                  return std::max({0.0, a - hi, lo - b});
                };
                const double ax = x * resolution, ay = y * resolution;
                const double bx = ax + resolution, by = ay + resolution;
                if (bound == ClearanceBound::kUpper) {
                  const double gx = gap(sx * h, (sx + 1) * h, ax, bx);
                  const double gy = gap(sy * h, (sy + 1) * h, ay, by);
                  expected = std::hypot(gx, gy) < clearance;
                } else {
                  const double cx = (sx + 0.5) * h, cy = (sy + 0.5) * h;
                  const double gx = gap(cx, cx, ax, bx), gy = gap(cy, cy, ay, by);
                  const double reach = clearance - h * std::numbers::sqrt2 / 2;
                  expected = (gx == 0 && gy == 0) || std::hypot(gx, gy) < reach;
                }
              }
            }
            if (sub.IsBlocked(sx, sy) != expected && ++mismatches <= 5) {
              ADD_FAILURE() << "sub-cell " << sx << "," << sy << " blocked "
                            << sub.IsBlocked(sx, sy) << ", expected " << expected;
            }
            const bool inside = grid.IsBlocked(sx / s, sy / s);
            blocked_near += expected && !inside ? 1 : 0;
          }
        }
        EXPECT_EQ(mismatches, 0);
        // The lower grid blocks sub-cells outside the obstacles once the clearance less half a
        // sub-cell diagonal reaches the nearest centres.
        if (bound == ClearanceBound::kUpper || clearance > h * (0.5 + std::numbers::sqrt2 / 2)) {
          EXPECT_GT(blocked_near, 0);
        }
      }
    }
  }
}

// On random grids: lower bound <= path returned, lower bound <= theta-star's length (a path
// that keeps the clearance), and the path returned keeps the clearance and joins the ends.
TEST(ExactAnyAngleClearanceTest, BoundsBracketThetaStarOnRandomGrids) {
  std::mt19937_64 rng(5);
  int compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const MapPtr map = GridMap(24, 24, RandomBlockedCells(rng, 24, 0.1));
    const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*map);
    const double r = trial % 2 == 0 ? 0.5 : 0.8;
    const Point2 start(1.5, 1.5), goal(22.5, 22.5);
    SCOPED_TRACE(trial);
    absl::StatusOr<PlanResult> upper =
        ::swarmplan::testing::PlanOnMap("exact-any-angle", map, start, goal, r);
    ASSERT_TRUE(upper.ok()) << upper.status();
    const double lower = PlannedLength(map, "exact-any-angle", start, goal, r, kLowerBound);
    const double theta = PlannedLength(map, "theta-star", start, goal, r);
    if (upper->found) {
      const Path& path = upper->raw_path;
      EXPECT_EQ(path.front(), Point3(start.x(), start.y(), 0));
      EXPECT_EQ(path.back(), Point3(goal.x(), goal.y(), 0));
      EXPECT_TRUE(checker->PathFree(path, r));
      ASSERT_GT(lower, 0.0);
      EXPECT_LE(lower, PathLength(path) * (1 + 1e-9));
    }
    if (theta > 0) {
      ASSERT_GT(lower, 0.0);
      EXPECT_LE(lower, theta * (1 + 1e-9));
      ++compared;
    }
  }
  EXPECT_GT(compared, 20);
}

// A one-cell door at clearance 0.5 fits only with no margin at all: only a path along the
// door's middle line keeps the clearance there. Straight through, the lower bound's own path
// keeps it and is returned; a path that must turn into the door would have to follow that line
// into it, which the path returned (a positive margin wherever it turns) does not: no path.
// The lower bound and theta-star (through cell centres) pass the door either way.
TEST(ExactAnyAngleClearanceTest, ADoorThatFitsWithNoMargin) {
  std::vector<Cell> wall;
  for (int y = 0; y < 7; ++y) {
    if (y != 3) wall.push_back({5, y});
  }
  const MapPtr map = GridMap(11, 7, wall);
  const Point2 start(1.5, 3.5), goal(9.5, 3.5);
  EXPECT_NEAR(PlannedLength(map, "exact-any-angle", start, goal, 0.5), 8.0, 1e-9);
  EXPECT_NEAR(PlannedLength(map, "exact-any-angle", start, goal, 0.5, kLowerBound), 8.0, 1e-9);
  const Point2 low(1.5, 0.5), high(9.5, 6.5);
  const double theta = PlannedLength(map, "theta-star", low, high, 0.5);
  const double lower = PlannedLength(map, "exact-any-angle", low, high, 0.5, kLowerBound);
  ASSERT_GT(theta, 0.0);
  ASSERT_GT(lower, 0.0);
  EXPECT_LE(lower, theta);
  EXPECT_LT(PlannedLength(map, "exact-any-angle", low, high, 0.5), 0.0);
  const double narrower = PlannedLength(map, "exact-any-angle", low, high, 0.45);
  EXPECT_GE(narrower, lower * (1 - 1e-9));
  EXPECT_LE(narrower, PlannedLength(map, "theta-star", low, high, 0.45) * (1 + 1e-9));
}

// margin: the path keeps the clearance plus the margin but for its first and last segments,
// which join ends that keep only the clearance.
TEST(ExactAnyAngleClearanceTest, MarginKeepsMoreButForTheEnds) {
  std::vector<Cell> wall;
  for (int x = 0; x < 20; ++x) wall.push_back({x, 4});
  for (int y = 5; y < 12; ++y) wall.push_back({10, y});
  const MapPtr map = GridMap(20, 20, wall);
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*map);
  const Point2 start(3.5, 5.5), goal(16.5, 5.5);  // 0.5 from the wall below
  absl::StatusOr<PlanResult> plain =
      ::swarmplan::testing::PlanOnMap("exact-any-angle", map, start, goal, 0.5);
  absl::StatusOr<PlanResult> roomy =
      ::swarmplan::testing::PlanOnMap("exact-any-angle", map, start, goal, 0.5, {{"margin", 1.0}});
  ASSERT_TRUE(plain.ok() && roomy.ok());
  ASSERT_TRUE(plain->found && roomy->found);
  const Path& path = roomy->raw_path;
  ASSERT_GE(path.size(), 4u);
  EXPECT_EQ(path.front(), Point3(start.x(), start.y(), 0));
  EXPECT_EQ(path.back(), Point3(goal.x(), goal.y(), 0));
  EXPECT_TRUE(checker->PathFree(path, 0.5));
  const Path inner(path.begin() + 1, path.end() - 1);
  EXPECT_GE(checker->PathClearance(inner), 1.5 - 1e-9);
  EXPECT_LT(checker->PathClearance(plain->raw_path), 1.0);
  EXPECT_GT(PathLength(path), PathLength(plain->raw_path));
}

// A grid made from another by blocking more cells (the seeds' corridor walls) gets the clearance
// grid of a rebuild from the other's, measured again only near the new cells.
TEST(ExactAnyAngleClearanceTest, ClearanceGridBlockingMatchesARebuild) {
  std::mt19937_64 rng(13);
  for (const auto& [width, height] : {std::pair{31, 23}, std::pair{600, 450}}) {
    std::bernoulli_distribution blocked(0.08);
    std::vector<int8_t> cells(static_cast<size_t>(width) * height, OccupancyGrid::kFree);
    for (int8_t& c : cells) c = blocked(rng) ? OccupancyGrid::kOccupied : OccupancyGrid::kFree;
    const OccupancyGrid base = *OccupancyGrid::Create(width, height, cells);
    std::uniform_int_distribution<int> x_of(0, width - 1), y_of(0, height - 1);
    std::vector<Cell> added = {{0, 0}, {width - 1, height - 1}, {0, height / 2}};
    for (int i = 0; i < 40; ++i) added.push_back({x_of(rng), y_of(rng)});
    for (const Cell& c : added) cells[static_cast<size_t>(c.y) * width + c.x] = 100;
    const OccupancyGrid cut = *OccupancyGrid::Create(width, height, cells);
    for (const double clearance : {0.3, 0.5, 1.0, 2.25}) {
      for (const ClearanceBound bound : {ClearanceBound::kUpper, ClearanceBound::kLower}) {
        SCOPED_TRACE(::testing::Message()
                     << width << " x " << height << " clearance " << clearance
                     << (bound == ClearanceBound::kUpper ? " upper" : " lower"));
        const OccupancyGrid patched = ClearanceGridBlocking(ClearanceGrid(base, clearance, bound),
                                                            cut, added, clearance, bound);
        const OccupancyGrid rebuilt = ClearanceGrid(cut, clearance, bound);
        ASSERT_EQ(patched.width(), rebuilt.width());
        ASSERT_EQ(patched.height(), rebuilt.height());
        EXPECT_EQ(patched.cells(), rebuilt.cells());
        EXPECT_NE(patched.cells(), ClearanceGrid(base, clearance, bound).cells());
        // The runs too: copied from the base's on the rows no new cell reaches.
        const AnyAngleGrid runs_patched = AnyAngleGrid::BuildBlocking(
            AnyAngleGrid::Build(base, clearance, bound), cut, added, clearance, bound);
        const AnyAngleGrid runs_rebuilt = AnyAngleGrid::Build(cut, clearance, bound);
        EXPECT_EQ(runs_patched.planning_grid().cells(), rebuilt.cells());
        EXPECT_EQ(runs_patched.planning_grid().BlockedCount(), rebuilt.BlockedCount());
        ASSERT_EQ(runs_patched.height(), runs_rebuilt.height());
        for (int y = 0; y < runs_rebuilt.height(); ++y) {
          const auto as_pairs = [&](const AnyAngleGrid& g) {
            std::vector<std::pair<int, int>> runs;
            for (const AnyAngleGrid::Run* r = g.RunsBegin(y); r != g.RunsEnd(y); ++r) {
              runs.emplace_back(r->begin, r->end);
            }
            return runs;
          };
          ASSERT_EQ(as_pairs(runs_patched), as_pairs(runs_rebuilt)) << "row " << y;
        }
      }
    }
  }
}

// exact-any-angle plans on a map patched from another exactly as on the same grid built anew.
TEST(ExactAnyAngleClearanceTest, APatchedMapPlansAsItsRebuild) {
  std::mt19937_64 rng(17);
  const std::vector<Cell> cells = RandomBlockedCells(rng, 40, 0.1);
  const MapPtr base = GridMap(40, 40, cells);
  std::vector<Cell> wall;
  for (int i = 5; i < 35; ++i) wall.push_back({i, 40 - i});
  std::vector<Cell> all = cells;
  all.insert(all.end(), wall.begin(), wall.end());
  const MapPtr rebuilt = GridMap(40, 40, all);
  const MapPtr patched =
      std::make_shared<const Map>(Map::Data(*rebuilt->grid()), Map::GridPatch{base, wall});
  // The base's clearance grids first, as the seed search builds them.
  ASSERT_TRUE(
      ::swarmplan::testing::PlanOnMap("exact-any-angle", base, {1.5, 1.5}, {38.5, 38.5}, 0.5).ok());
  for (const double margin : {0.0, 1.0}) {
    SCOPED_TRACE(margin);
    const ParamValues params = {{"margin", margin}};
    absl::StatusOr<PlanResult> on_patched = ::swarmplan::testing::PlanOnMap(
        "exact-any-angle", patched, {1.5, 1.5}, {38.5, 38.5}, 0.5, params);
    absl::StatusOr<PlanResult> on_rebuilt = ::swarmplan::testing::PlanOnMap(
        "exact-any-angle", rebuilt, {1.5, 1.5}, {38.5, 38.5}, 0.5, params);
    ASSERT_TRUE(on_patched.ok() && on_rebuilt.ok());
    ASSERT_EQ(on_patched->found, on_rebuilt->found);
    EXPECT_EQ(on_patched->raw_path, on_rebuilt->raw_path);
  }
}

}  // namespace
}  // namespace swarmplan
