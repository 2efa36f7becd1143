#include "bench/papers/as_bfo_islands_world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "absl/strings/str_cat.h"
#include "core/graph/grid_search.h"
#include "core/random.h"

namespace swarmplan::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Island centres keep this far (unit square) from the start and goal corners.
constexpr double kCornerClearance = 0.2;
constexpr int kMaxTries = 1000;

// How deep a point lies inside the islands: the largest radius - distance over the discs
// (negative outside every disc).
double Depth(const std::vector<IslandDisc>& discs, const Point2& p) {
  double depth = -std::numeric_limits<double>::infinity();
  for (const IslandDisc& disc : discs)
    depth = std::max(depth, disc.radius - (p - disc.centre).norm());
  return depth;
}

bool NearCorner(const Point2& p) {
  return p.norm() < kCornerClearance || (p - Point2(1.0, 1.0)).norm() < kCornerClearance;
}

}  // namespace

const std::vector<IslandEnvironmentSpec>& AsBfoEnvironments() {
  static const std::vector<IslandEnvironmentSpec>* const environments =
      new std::vector<IslandEnvironmentSpec>{
          // A few large islands.
          {"env1", 2019, 8, 0.06, 0.11, 0.3},
          // More, smaller islands.
          {"env2", 4031, 18, 0.035, 0.07, 0.3},
      };
  return *environments;
}

const std::vector<int>& AsBfoSizes() {
  static const std::vector<int>* const sizes = new std::vector<int>{10, 15, 20, 25, 30};
  return *sizes;
}

Cell IslandStart(int) { return Cell{0, 0}; }
Cell IslandGoal(int n) { return Cell{n - 1, n - 1}; }

std::vector<IslandDisc> DrawIslands(const IslandEnvironmentSpec& spec, uint64_t seed) {
  Rng rng(seed);
  std::vector<IslandDisc> discs;
  for (int i = 0; i < spec.islands; ++i) {
    Point2 centre;
    do {
      centre = Point2(rng.Uniform(0.05, 0.95), rng.Uniform(0.05, 0.95));
    } while (NearCorner(centre));
    const double radius = rng.Uniform(spec.min_radius, spec.max_radius);
    discs.push_back({centre, radius});
    const int lobes = static_cast<int>(rng.UniformInt(2, 4));
    for (int j = 0; j < lobes; ++j) {
      const double angle = rng.Uniform(0.0, 2.0 * kPi);
      const double offset = rng.Uniform(0.5, 0.9) * radius;
      const double lobe_radius = rng.Uniform(0.5, 0.8) * radius;
      // offset < radius: the lobe's centre lies inside the main disc, so the blob is connected.
      discs.push_back({centre + offset * Point2(std::cos(angle), std::sin(angle)), lobe_radius});
    }
  }
  return discs;
}

absl::StatusOr<OccupancyGrid> RasteriseIslands(const std::vector<IslandDisc>& discs, int n,
                                               double obstacle_ratio) {
  if (n < 2) return absl::InvalidArgumentError(absl::StrCat("island grid size ", n, " < 2"));
  if (!(obstacle_ratio >= 0.0 && obstacle_ratio < 1.0)) {
    return absl::InvalidArgumentError(
        absl::StrCat("island obstacle ratio ", obstacle_ratio, " is not in [0, 1)"));
  }
  const size_t count = static_cast<size_t>(n) * n;
  std::vector<double> depth(count);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      depth[static_cast<size_t>(y) * n + x] = Depth(discs, Point2((x + 0.5) / n, (y + 0.5) / n));
    }
  }
  const Cell start = IslandStart(n);
  const Cell goal = IslandGoal(n);
  std::vector<size_t> order;
  for (size_t i = 0; i < count; ++i) {
    const Cell c{static_cast<int>(i % n), static_cast<int>(i / n)};
    if (c != start && c != goal) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return depth[a] > depth[b]; });
  const size_t blocked = static_cast<size_t>(std::lround(obstacle_ratio * count));
  std::vector<int8_t> cells(count, OccupancyGrid::kFree);
  for (size_t i = 0; i < blocked && i < order.size(); ++i) {
    cells[order[i]] = OccupancyGrid::kOccupied;
  }
  return OccupancyGrid::Create(n, n, std::move(cells));
}

absl::StatusOr<IslandLayout> AcceptedIslands(const IslandEnvironmentSpec& spec,
                                             const std::vector<int>& sizes) {
  for (int t = 0; t < kMaxTries; ++t) {
    IslandLayout layout{DrawIslands(spec, spec.seed + t), spec.seed + t};
    bool accepted = true;
    for (int n : sizes) {
      absl::StatusOr<OccupancyGrid> grid = RasteriseIslands(layout.discs, n, spec.obstacle_ratio);
      if (!grid.ok()) return grid.status();
      const GridSearchResult path = SearchGrid(*grid, IslandStart(n), IslandGoal(n));
      if (!path.found || path.length <= (n - 1) * std::sqrt(2.0) + 1e-9) {
        accepted = false;
        break;
      }
    }
    if (accepted) return layout;
  }
  return absl::FailedPreconditionError(
      absl::StrCat("island environment ", spec.name, ": no seed in [", spec.seed, ", ",
                   spec.seed + kMaxTries, ") gives connected worlds at every size"));
}

int CountIslands(const OccupancyGrid& grid) {
  const int w = grid.width();
  const int h = grid.height();
  std::vector<uint8_t> seen(static_cast<size_t>(w) * h, 0);
  int islands = 0;
  std::vector<Cell> stack;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!grid.IsBlocked(x, y) || seen[static_cast<size_t>(y) * w + x]) continue;
      ++islands;
      seen[static_cast<size_t>(y) * w + x] = 1;
      stack.push_back(Cell{x, y});
      while (!stack.empty()) {
        const Cell c = stack.back();
        stack.pop_back();
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const Cell d{c.x + dx, c.y + dy};
            if (!grid.InBounds(d) || !grid.IsBlocked(d)) continue;
            uint8_t& mark = seen[static_cast<size_t>(d.y) * w + d.x];
            if (!mark) {
              mark = 1;
              stack.push_back(d);
            }
          }
        }
      }
    }
  }
  return islands;
}

std::string IslandWorldFile(const std::string& environment, int n) {
  return absl::StrCat(environment, "-", n, "x", n, ".txt");
}

}  // namespace swarmplan::bench
