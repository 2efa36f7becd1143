#include "bench/papers/bpso_vertices_encoding.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "core/geometry/obstacle_vertices.h"

namespace swarmplan::bench {

std::optional<double> BestOrderedVertexPath(const ShapeWorld& world, const Point2& start,
                                            const Point2& goal, double clearance,
                                            double circle_tolerance) {
  const double side = std::max(world.bounds().Width(), world.bounds().Height());
  const GrownObstacles grown = GrowObstacles(world, clearance, circle_tolerance * side);
  // The planner's order: corners by x then y, stable-sorted by projection on start -> goal.
  const Point2 axis = goal - start;
  const double len2 = std::max(axis.squaredNorm(), 1e-300);
  std::vector<std::pair<double, Point2>> keyed;
  for (const GrownObstacles::Corner& c : grown.corners) {
    keyed.push_back({(c.point - start).dot(axis) / len2, c.point});
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Point2> nodes{start};
  for (const auto& [t, p] : keyed) nodes.push_back(p);
  nodes.push_back(goal);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> best(nodes.size(), kInf);
  best[0] = 0.0;
  for (size_t j = 1; j < nodes.size(); ++j) {
    for (size_t i = 0; i < j; ++i) {
      if (best[i] == kInf) continue;
      const double candidate = best[i] + (nodes[j] - nodes[i]).norm();
      if (candidate < best[j] && !grown.Blocks(nodes[i], nodes[j])) best[j] = candidate;
    }
  }
  if (best.back() == kInf) return std::nullopt;
  return best.back();
}

}  // namespace swarmplan::bench
