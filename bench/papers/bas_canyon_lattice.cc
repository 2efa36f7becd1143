#include "bench/papers/bas_canyon_lattice.h"

#include <cmath>
#include <limits>
#include <vector>

#include "core/algorithms/bas/terrain_objective.h"

namespace swarmplan::bench {

absl::StatusOr<LatticePath> LatticeOptimum(const Problem& problem, const LatticeOptions& options) {
  absl::StatusOr<std::unique_ptr<TerrainObjective>> created =
      TerrainObjective::Create(problem, 0.0);
  if (!created.ok()) return created.status();
  const TerrainObjective& objective = **created;
  const Terrain& terrain = objective.terrain();
  const int ys = static_cast<int>(std::floor((terrain.depth() - 1) / options.y_step + 1e-9)) + 1;
  const double z_max =
      std::min(terrain.ceiling(), terrain.max_height() + options.max_above_highest_ground);
  const int zs =
      static_cast<int>(std::floor((z_max - terrain.min_height()) / options.z_step + 1e-9)) + 1;
  const int reach = static_cast<int>(std::floor(options.max_dy / options.y_step + 1e-9));
  const int states = ys * zs;
  const int columns = objective.columns();
  const double inf = std::numeric_limits<double>::infinity();
  const auto point = [&](int column, int state) {
    return Point3(objective.ColumnX(column),
                  terrain.ToWorld(Point2(0, (state / zs) * options.y_step)).y(),
                  terrain.min_height() + (state % zs) * options.z_step);
  };
  const auto step_cost = [&](const Point3& a, const Point3& b) {
    if (objective.SegmentViolation(a, b) > 0.0) return inf;
    return (b - a).norm() + b.z();
  };

  // cost[c][s]: the best fitness from the start to waypoint s of column c; from[c][s] its
  // predecessor in column c - 1.
  std::vector<std::vector<double>> cost(columns, std::vector<double>(states, inf));
  std::vector<std::vector<int>> from(columns, std::vector<int>(states, -1));
  for (int s = 0; s < states; ++s) cost[0][s] = step_cost(objective.start(), point(0, s));
  for (int c = 1; c < columns; ++c) {
    for (int s = 0; s < states; ++s) {
      if (cost[c - 1][s] == inf) continue;
      const Point3 a = point(c - 1, s);
      const int y = s / zs;
      for (int ny = std::max(0, y - reach); ny <= std::min(ys - 1, y + reach); ++ny) {
        for (int nz = 0; nz < zs; ++nz) {
          const int n = ny * zs + nz;
          const Point3 b = point(c, n);
          // The ground under b rules out the lower levels without sampling the segment.
          if (b.z() < terrain.GroundAt(b.head<2>()) + problem.clearance) continue;
          const double total = cost[c - 1][s] + step_cost(a, b);
          if (total < cost[c][n]) {
            cost[c][n] = total;
            from[c][n] = s;
          }
        }
      }
    }
  }
  double best = inf;
  int last = -1;
  for (int s = 0; s < states; ++s) {
    const double total = cost[columns - 1][s] + step_cost(point(columns - 1, s), objective.goal());
    if (total < best) {
      best = total;
      last = s;
    }
  }
  if (last < 0) return absl::NotFoundError("no feasible lattice path");
  LatticePath result;
  result.fitness = best;
  result.path.resize(columns + 2);
  result.path.front() = objective.start();
  result.path.back() = objective.goal();
  for (int c = columns - 1, s = last; c >= 0; s = from[c][s], --c) result.path[c + 1] = point(c, s);
  return result;
}

}  // namespace swarmplan::bench
