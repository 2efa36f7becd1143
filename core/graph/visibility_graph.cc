#include "core/graph/visibility_graph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <queue>

#include "absl/status/status.h"
#include "absl/strings/str_format.h"
#include "core/geometry/obstacle_vertices.h"
#include "core/geometry/shape_collision.h"

namespace swarmplan {
namespace {

absl::Status CheckEndpoint(const ShapeWorld& world, const ShapeCollisionChecker& checker,
                           const Point2& p, double clearance, const char* name) {
  if (!p.allFinite()) {
    return absl::InvalidArgumentError(absl::StrFormat("%s: coordinates must be finite", name));
  }
  if (!world.bounds().Contains(p)) {
    return absl::FailedPreconditionError(
        absl::StrFormat("%s (%g, %g) is outside the map", name, p.x(), p.y()));
  }
  if (checker.Clearance(Point3(p.x(), p.y(), 0.0)) < clearance) {
    return absl::FailedPreconditionError(
        absl::StrFormat("%s (%g, %g) is inside an obstacle or closer than the clearance %g to one",
                        name, p.x(), p.y(), clearance));
  }
  return absl::OkStatus();
}

absl::Status CheckInputs(const ShapeWorld& world, const ShapeCollisionChecker& checker,
                         const Point2& start, const Point2& goal, double clearance,
                         double circle_tolerance) {
  if (!std::isfinite(clearance) || clearance < 0) {
    return absl::InvalidArgumentError("clearance: must be a finite number >= 0");
  }
  if (!std::isfinite(circle_tolerance) || circle_tolerance <= 0) {
    return absl::InvalidArgumentError("circle_tolerance: must be a finite number > 0");
  }
  if (absl::Status s = CheckEndpoint(world, checker, start, clearance, "start"); !s.ok()) {
    return s;
  }
  return CheckEndpoint(world, checker, goal, clearance, "goal");
}

// A* over the visibility graph of the grown obstacles; the inputs are valid.
absl::StatusOr<Path> SearchVisibilityGraph(const ShapeCollisionChecker& checker,
                                           const GrownObstacles& grown, const Point2& start,
                                           const Point2& goal, double clearance) {
  // An end may keep the clearance yet lie in the slack between a grown piece and the true
  // offset; its edges are then checked exactly instead.
  const bool start_in_slack = grown.Contains(start);
  const bool goal_in_slack = grown.Contains(goal);
  auto visible = [&](int from, int to, const Point2& a, const Point2& b) {
    if ((start_in_slack && (from == 0 || to == 0)) || (goal_in_slack && (from == 1 || to == 1))) {
      return checker.SegmentFree(Point3(a.x(), a.y(), 0.0), Point3(b.x(), b.y(), 0.0), clearance);
    }
    return !grown.Blocks(a, b);
  };
  if (visible(0, 1, start, goal)) {
    return Path{Point3(start.x(), start.y(), 0.0), Point3(goal.x(), goal.y(), 0.0)};
  }

  // Nodes: 0 is the start, 1 the goal, 2 + k the k-th corner. A* with the straight-line
  // heuristic over the complete graph; an edge's visibility is tested only when it would
  // improve its end, and only for edges tangent to the pieces at the corners they touch.
  const int corners = static_cast<int>(grown.corners.size());
  const int nodes = corners + 2;
  auto point = [&](int i) -> const Point2& {
    return i == 0 ? start : i == 1 ? goal : grown.corners[i - 2].point;
  };
  auto tangent = [&](int from, int to) {  // an end in the slack sees corners from inside
    return to < 2 || (from == 0 && start_in_slack) || (from == 1 && goal_in_slack) ||
           grown.Tangent(point(from), grown.corners[to - 2]);
  };
  std::vector<double> cost(nodes, kInf);
  std::vector<int> parent(nodes, -1);
  std::vector<char> closed(nodes, 0);
  using Entry = std::pair<double, int>;  // (cost + heuristic, node)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[0] = 0.0;
  open.push({(goal - start).norm(), 0});
  while (!open.empty()) {
    const int u = open.top().second;
    open.pop();
    if (closed[u]) continue;
    closed[u] = 1;
    if (u == 1) break;
    const Point2& pu = point(u);
    for (int v = 1; v < nodes; ++v) {
      if (closed[v] || v == u) continue;
      const Point2& pv = point(v);
      const double candidate = cost[u] + (pv - pu).norm();
      if (candidate >= cost[v]) continue;
      if (!tangent(u, v) || !tangent(v, u) || !visible(u, v, pu, pv)) continue;
      cost[v] = candidate;
      parent[v] = u;
      open.push({candidate + (goal - pv).norm(), v});
    }
  }
  if (parent[1] < 0) {
    return absl::NotFoundError(
        absl::StrFormat("visibility graph: no path from (%g, %g) to (%g, %g) with clearance %g",
                        start.x(), start.y(), goal.x(), goal.y(), clearance));
  }
  Path path;
  for (int v = 1; v >= 0; v = parent[v]) path.push_back(Point3(point(v).x(), point(v).y(), 0.0));
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace

absl::StatusOr<Path> ShortestPathVisibility(const ShapeWorld& world, const Point2& start,
                                            const Point2& goal, double clearance,
                                            double circle_tolerance) {
  const ShapeCollisionChecker checker(world);
  if (absl::Status s = CheckInputs(world, checker, start, goal, clearance, circle_tolerance);
      !s.ok()) {
    return s;
  }
  return SearchVisibilityGraph(checker, GrowObstacles(world, clearance, circle_tolerance), start,
                               goal, clearance);
}

absl::StatusOr<Path> ShortestPathVisibility(const Map& map, const Point2& start, const Point2& goal,
                                            double clearance, double circle_tolerance) {
  const ShapeWorld* world = map.world();
  if (world == nullptr) {
    return absl::InvalidArgumentError("visibility graph: the map is not a shape world");
  }
  const ShapeCollisionChecker checker(*world);
  if (absl::Status s = CheckInputs(*world, checker, start, goal, clearance, circle_tolerance);
      !s.ok()) {
    return s;
  }
  const std::shared_ptr<const GrownObstacles> grown = map.Derived<GrownObstacles>(
      absl::StrFormat("grown-obstacles radius=%a tolerance=%a", clearance, circle_tolerance),
      [&] { return GrowObstacles(*world, clearance, circle_tolerance); });
  return SearchVisibilityGraph(checker, *grown, start, goal, clearance);
}

}  // namespace swarmplan
