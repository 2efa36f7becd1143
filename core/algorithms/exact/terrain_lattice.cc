#include "core/algorithms/exact/terrain_lattice.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "core/geometry/terrain_collision.h"
#include "core/operators/terrain_path_cost.h"
#include "core/stop_token.h"

namespace swarmplan {
namespace {

// The search graph: lattice nodes 0..nodes-1, node = (j * width + i) * levels + k, then the
// start and the goal.
class LatticeSearch {
 public:
  LatticeSearch(const Terrain& terrain, const Point3& start, const Point3& goal, double clearance,
                const TerrainLatticeLevels& levels)
      : terrain_(terrain),
        checker_(terrain),
        start_(start),
        goal_(goal),
        clearance_(clearance),
        levels_(levels),
        nodes_(static_cast<int64_t>(terrain.width()) * terrain.depth() * levels.count),
        start_node_(nodes_),
        goal_node_(nodes_ + 1),
        start_cell_(terrain.ToCell(start.head<2>())),
        goal_cell_(terrain.ToCell(goal.head<2>())) {
    lowest_.resize(static_cast<size_t>(terrain.width()) * terrain.depth());
    for (int j = 0; j < terrain.depth(); ++j) {
      for (int i = 0; i < terrain.width(); ++i) lowest_[Column(i, j)] = LowestLevel(i, j);
    }
    // The least the objective can charge per unit of travel, for the heuristic: every segment
    // ends at a level or at the goal, so at a height >= LowestEnd().
    const double low = LowestEnd(), cell = terrain.cell_size();
    height_weight_ = std::max(0.0, low) / cell;
    length_weight_ = low < 0.0 ? 1.0 + low / cell : 1.0;
  }

  // The lowest height at which a segment of the graph can end.
  double LowestEnd() const {
    return levels_.count > 0 ? std::min(levels_.base, goal_.z()) : goal_.z();
  }

  TerrainLatticeResult Run(const StopToken* stop) {
    TerrainLatticeResult result;
    result.nodes = nodes_;
    result.levels = levels_;
    const size_t total = static_cast<size_t>(nodes_ + 2);
    std::vector<double> g(total, kInf);
    std::vector<int32_t> parent(total, -1);
    std::vector<uint8_t> closed(total, 0);
    using Entry = std::pair<double, int64_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    g[start_node_] = 0.0;
    open.push({Heuristic(start_), start_node_});
    const auto relax = [&](int64_t from, const Point3& a, int64_t to, const Point3& b) {
      if (closed[to]) return;
      const double candidate = g[from] + TerrainSegmentCost(a, b, terrain_.cell_size());
      if (!(candidate < g[to])) return;
      if (!checker_.SegmentFree(a, b, clearance_)) return;
      g[to] = candidate;
      parent[to] = static_cast<int32_t>(from);
      open.push({candidate + Heuristic(b), to});
    };
    while (!open.empty()) {
      const int64_t node = open.top().second;
      open.pop();
      if (closed[node]) continue;
      closed[node] = 1;
      ++result.expanded;
      if (stop != nullptr && result.expanded % kStopCheckInterval == 0 &&
          stop->Check(0) != StopReason::kNone) {
        result.stopped = true;
        return result;
      }
      if (node == goal_node_) break;
      const Point3 a = Position(node);
      if (node == start_node_) {
        ForEachNodeNear(start_cell_, start_.z(),
                        [&](int64_t n) { relax(node, a, n, Position(n)); });
        relax(node, a, goal_node_, goal_);
        continue;
      }
      const int k = static_cast<int>(node % levels_.count);
      const int64_t column = node / levels_.count;
      const int i = static_cast<int>(column % terrain_.width());
      const int j = static_cast<int>(column / terrain_.width());
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const int ni = i + di, nj = j + dj;
          if (!terrain_.InBounds(ni, nj)) continue;
          const int low = lowest_[Column(ni, nj)];
          for (int nk = std::max(k - 1, low); nk <= std::min(k + 1, levels_.count - 1); ++nk) {
            if (di == 0 && dj == 0 && nk == k) continue;
            const int64_t n = Node(ni, nj, nk);
            relax(node, a, n, Position(n));
          }
        }
      }
      if (Near(i, j, k, goal_cell_, goal_.z())) relax(node, a, goal_node_, goal_);
    }
    if (g[goal_node_] == kInf) return result;
    for (int64_t n = goal_node_; n >= 0; n = parent[n]) {
      const Point3 p = Position(n);
      if (result.path.empty() || result.path.back() != p) result.path.push_back(p);
      if (n == start_node_) break;
    }
    std::reverse(result.path.begin(), result.path.end());
    result.cost = TerrainPathCost(result.path, terrain_.cell_size());
    return result;
  }

 private:
  size_t Column(int i, int j) const { return static_cast<size_t>(j) * terrain_.width() + i; }
  int64_t Node(int i, int j, int k) const {
    return static_cast<int64_t>(Column(i, j)) * levels_.count + k;
  }
  double LevelZ(int k) const { return levels_.base + k * levels_.step; }
  Point3 NodePosition(int i, int j, int k) const {
    const Point2 xy = terrain_.CellCentre(i, j);
    return Point3(xy.x(), xy.y(), LevelZ(k));
  }
  Point3 Position(int64_t node) const {
    if (node == start_node_) return start_;
    if (node == goal_node_) return goal_;
    const int k = static_cast<int>(node % levels_.count);
    const int64_t column = node / levels_.count;
    return NodePosition(static_cast<int>(column % terrain_.width()),
                        static_cast<int>(column / terrain_.width()), k);
  }
  // The lowest usable level of a column (levels_.count when none): clearance grows with z.
  int LowestLevel(int i, int j) const {
    for (int k = 0; k < levels_.count; ++k) {
      if (checker_.Clearance(NodePosition(i, j, k)) >= clearance_) return k;
    }
    return levels_.count;
  }
  bool Near(int i, int j, int k, const Point2& cell, double z) const {
    return std::abs(i - cell.x()) <= 1.0 && std::abs(j - cell.y()) <= 1.0 &&
           std::abs(LevelZ(k) - z) <= levels_.step;
  }
  template <typename Visit>
  void ForEachNodeNear(const Point2& cell, double z, Visit&& visit) const {
    for (int j = static_cast<int>(std::ceil(cell.y() - 1.0));
         j <= static_cast<int>(std::floor(cell.y() + 1.0)); ++j) {
      for (int i = static_cast<int>(std::ceil(cell.x() - 1.0));
           i <= static_cast<int>(std::floor(cell.x() + 1.0)); ++i) {
        if (!terrain_.InBounds(i, j)) continue;
        for (int k = lowest_[Column(i, j)]; k < levels_.count; ++k) {
          if (Near(i, j, k, cell, z)) visit(Node(i, j, k));
        }
      }
    }
  }
  // A lower bound on the cost from p to the goal: each segment costs at least
  // length_weight * its length + height_weight * its x-advance (see the constructor).
  double Heuristic(const Point3& p) const {
    return length_weight_ * (goal_ - p).norm() + height_weight_ * std::abs(goal_.x() - p.x());
  }

  const Terrain& terrain_;
  TerrainCollisionChecker checker_;
  Point3 start_, goal_;
  double clearance_;
  TerrainLatticeLevels levels_;
  int64_t nodes_;
  int64_t start_node_, goal_node_;
  Point2 start_cell_, goal_cell_;
  std::vector<int> lowest_;
  double height_weight_ = 0.0;
  double length_weight_ = 1.0;
};

}  // namespace

absl::StatusOr<TerrainLatticeLevels> MakeTerrainLatticeLevels(
    const Terrain& terrain, double clearance, const TerrainLatticeOptions& options) {
  if (!std::isfinite(options.vertical_step) || options.vertical_step < 0) {
    return absl::InvalidArgumentError(absl::StrCat(
        "terrain lattice: vertical_step must be >= 0 (0: automatic), got ", options.vertical_step));
  }
  if (options.max_levels < 2) {
    return absl::InvalidArgumentError(
        absl::StrCat("terrain lattice: max_levels must be >= 2, got ", options.max_levels));
  }
  TerrainLatticeLevels levels;
  levels.base = terrain.min_height() + clearance;
  const double span = terrain.ceiling() - levels.base;
  if (span < 0) {
    levels.count = 0;
    return levels;
  }
  levels.step = options.vertical_step;
  if (levels.step == 0.0) {
    levels.step = terrain.cell_size();
    if (span / levels.step + 1 > options.max_levels) levels.step = span / (options.max_levels - 1);
  }
  const double count = std::floor(span / levels.step * (1 + 1e-12)) + 1;
  levels.count = static_cast<int>(std::min(count, 1e9));
  return levels;
}

absl::StatusOr<TerrainLatticeResult> TerrainLatticeOptimum(const Terrain& terrain,
                                                           const Point3& start, const Point3& goal,
                                                           double clearance,
                                                           const TerrainLatticeOptions& options) {
  for (const auto& [p, field] : {std::pair{&start, "start"}, std::pair{&goal, "goal"}}) {
    const Point2 lo = terrain.min_xy(), hi = terrain.max_xy();
    if (!(p->x() >= lo.x() && p->y() >= lo.y() && p->x() <= hi.x() && p->y() <= hi.y()) ||
        !std::isfinite(p->z())) {
      return absl::InvalidArgumentError(absl::StrCat("terrain lattice: ", field, " (", p->x(), ", ",
                                                     p->y(), ", ", p->z(),
                                                     ") is not a point over the terrain"));
    }
  }
  absl::StatusOr<TerrainLatticeLevels> levels =
      MakeTerrainLatticeLevels(terrain, clearance, options);
  if (!levels.ok()) return levels.status();
  const double nodes = static_cast<double>(terrain.width()) * terrain.depth() * levels->count;
  if (nodes > static_cast<double>(kMaxTerrainLatticeNodes)) {
    return absl::ResourceExhaustedError(
        absl::StrCat("terrain lattice: ", terrain.width(), " x ", terrain.depth(), " cells x ",
                     levels->count, " height levels = ", nodes, " nodes exceeds the limit of ",
                     kMaxTerrainLatticeNodes, "; raise vertical_step or lower max_levels"));
  }
  LatticeSearch search(terrain, start, goal, clearance, *levels);
  if (search.LowestEnd() < -terrain.cell_size()) {
    return absl::FailedPreconditionError(absl::StrCat(
        "terrain lattice: the lowest flight height ", search.LowestEnd(),
        " is below minus the cell size ", -terrain.cell_size(),
        "; the objective charges heights counted from zero, so some segments would have a "
        "negative cost"));
  }
  return search.Run(options.stop);
}

}  // namespace swarmplan
