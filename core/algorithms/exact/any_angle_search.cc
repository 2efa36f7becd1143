#include "core/algorithms/exact/any_angle_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

#include "absl/container/flat_hash_map.h"
#include "core/stop_token.h"

namespace swarmplan {
namespace {

// Tolerance (cells) of interval comparisons: rays are recomputed in floating point from the
// root, so an endpoint that should be a lattice value may be off by a few ulps.
constexpr double kTol = 1e-9;

struct Root {
  Point2 p;
  int parent;  // -1 for the start
  double g;
};

// All points of [a, b] on row `row` are visible from `root`; `goal` nodes end the search.
struct Node {
  int row;
  double a, b;
  int root;
  bool goal;
};

struct QueueEntry {
  double f;
  double g;
  int node;
  bool operator<(const QueueEntry& o) const {
    if (f != o.f) return f > o.f;
    return g < o.g;
  }
};

// The lattice points x >= `from` of a cell row where it changes between blocked and free (cells
// x - 1 and x differ; outside the grid is blocked): its runs' ends, in increasing order. A convex
// corner (one blocked cell of four) can lie only at a change of one of its two rows.
class RowChanges {
 public:
  RowChanges(const AnyAngleGrid& grid, int row, int from)
      : run_(std::lower_bound(grid.RunsBegin(row), grid.RunsEnd(row), from,
                              [](const AnyAngleGrid::Run& run, int x) { return run.end < x; })),
        end_(grid.RunsEnd(row)) {
    if (Peek() < from) Next();
  }
  // The next change, or INT_MAX past the last.
  int Peek() const {
    if (run_ == end_) return std::numeric_limits<int>::max();
    return at_begin_ ? run_->begin : run_->end;
  }
  void Next() {
    if (!at_begin_) ++run_;
    at_begin_ = !at_begin_;
  }

 private:
  const AnyAngleGrid::Run* run_;
  const AnyAngleGrid::Run* end_;
  bool at_begin_ = true;
};

// The next change of either row (each taken once), or INT_MAX past the last.
int NextChange(RowChanges& a, RowChanges& b) {
  const int x = std::min(a.Peek(), b.Peek());
  if (a.Peek() == x) a.Next();
  if (b.Peek() == x) b.Next();
  return x;
}

class Search {
 public:
  Search(const AnyAngleGrid& grid, const Point2& start, const Point2& goal, const StopToken* stop)
      : grid_(grid), start_(start), goal_(goal), stop_(stop), width_(grid.width()) {
    BuildRows();
  }

  AnyAngleSearchResult Run() {
    AnyAngleSearchResult result;
    if (start_ == goal_) {
      result.found = true;
      result.vertices = {start_, goal_};
      return result;
    }
    roots_.push_back(Root{start_, -1, 0.0});
    const int js = start_row_;
    const double sx = start_.x();
    Push(js, sx, ReachRight(js, sx), 0);
    Push(js, ReachLeft(js, sx), sx, 0);
    const int cell = std::min(static_cast<int>(std::floor(sx)), width_ - 1);
    if (const AnyAngleGrid::Run* run = grid_.RunAt(up_[js], cell); run != nullptr) {
      Push(js + 1, run->begin, run->end, 0);
    }
    if (const AnyAngleGrid::Run* run = grid_.RunAt(down_[js], cell); run != nullptr) {
      Push(js - 1, run->begin, run->end, 0);
    }
    while (!open_.empty()) {
      const QueueEntry top = open_.top();
      open_.pop();
      const Node node = nodes_[top.node];
      if (node.goal) {
        result.found = true;
        result.length = top.f;
        result.vertices = PathTo(node.root);
        result.expanded = expanded_;
        return result;
      }
      if (Superseded(node.root)) continue;
      ++expanded_;
      if (stop_ != nullptr && expanded_ % kStopCheckInterval == 0 &&
          stop_->Check(0) != StopReason::kNone) {
        result.stopped = true;
        result.expanded = expanded_;
        return result;
      }
      const Root root = roots_[node.root];
      if (ys_[node.row] == root.p.y()) {
        ExpandFlat(node, root);
      } else {
        ExpandCone(node, root);
      }
    }
    result.expanded = expanded_;
    return result;
  }

 private:
  // The rows are the grid lines y = 0..height plus the lines through the start and the goal;
  // up_[j] / down_[j] are the cell rows of the bands above and below row j (out of the grid,
  // hence blocked, past the edges).
  void BuildRows() {
    for (int y = 0; y <= grid_.height(); ++y) ys_.push_back(y);
    ys_.push_back(start_.y());
    ys_.push_back(goal_.y());
    std::sort(ys_.begin(), ys_.end());
    ys_.erase(std::unique(ys_.begin(), ys_.end()), ys_.end());
    const int m = static_cast<int>(ys_.size());
    up_.resize(m);
    down_.resize(m);
    lattice_.resize(m);
    for (int j = 0; j < m; ++j) {
      up_[j] =
          j + 1 < m ? static_cast<int>(std::floor(0.5 * (ys_[j] + ys_[j + 1]))) : grid_.height();
      down_[j] = j > 0 ? static_cast<int>(std::floor(0.5 * (ys_[j - 1] + ys_[j]))) : -1;
      lattice_[j] = ys_[j] == std::floor(ys_[j]);
    }
    start_row_ = RowOf(start_.y());
    goal_row_ = RowOf(goal_.y());
  }

  int RowOf(double y) const {
    return static_cast<int>(std::lower_bound(ys_.begin(), ys_.end(), y) - ys_.begin());
  }

  bool Free(int x, int cell_row) const { return !grid_.Blocked(x, cell_row); }

  // Moving along row j through the lattice point x needs a band on which both sides are free.
  bool PassesAlongRow(int j, int x) const {
    return (Free(x - 1, up_[j]) && Free(x, up_[j])) || (Free(x - 1, down_[j]) && Free(x, down_[j]));
  }

  // How far along row j a straight move from x reaches to the right / left.
  double ReachRight(int j, double x) const {
    const int col = static_cast<int>(std::floor(x));
    if (col >= width_ || !(Free(col, up_[j]) || Free(col, down_[j]))) return x;
    int cur = col + 1;
    while (cur < width_ && PassesAlongRow(j, cur)) ++cur;
    return cur;
  }
  double ReachLeft(int j, double x) const {
    const int col = static_cast<int>(std::ceil(x)) - 1;
    if (col < 0 || !(Free(col, up_[j]) || Free(col, down_[j]))) return x;
    int cur = col;
    while (cur > 0 && PassesAlongRow(j, cur)) --cur;
    return cur;
  }

  // Lower bound of the cost to the goal through [a, b] on row j from root r.
  double Heuristic(int j, double a, double b, const Point2& r) const {
    const double y = ys_[j];
    if (r.y() == y) {
      const double px = std::clamp(r.x(), a, b);
      return std::abs(px - r.x()) + (Point2(px, y) - goal_).norm();
    }
    Point2 target = goal_;
    if ((goal_.y() - y) * (r.y() - y) > 0) target.y() = 2 * y - goal_.y();
    const double cross = r.x() + (target.x() - r.x()) * (y - r.y()) / (target.y() - r.y());
    const Point2 p(std::clamp(cross, a, b), y);
    return (p - r).norm() + (target - p).norm();
  }

  void Push(int j, double a, double b, int root) {
    if (a > b) return;
    const Root& r = roots_[root];
    if (j == goal_row_ && goal_.x() >= a - kTol && goal_.x() <= b + kTol) {
      const double f = r.g + (goal_ - r.p).norm();
      nodes_.push_back(Node{j, goal_.x(), goal_.x(), root, true});
      open_.push(QueueEntry{f, f, static_cast<int>(nodes_.size()) - 1});
    }
    nodes_.push_back(Node{j, a, b, root, false});
    open_.push(QueueEntry{r.g + Heuristic(j, a, b, r.p), r.g, static_cast<int>(nodes_.size()) - 1});
  }

  int64_t LatticeKey(const Point2& p) const {
    return static_cast<int64_t>(p.y()) * (width_ + 1) + static_cast<int64_t>(p.x());
  }

  // A new root at the convex corner c reached from `parent`, or -1 when c already is a root
  // at least as cheap (root-level pruning).
  int NewRoot(const Point2& c, int parent) {
    const double g = roots_[parent].g + (c - roots_[parent].p).norm();
    const int index = static_cast<int>(roots_.size());
    auto [it, inserted] = best_root_.try_emplace(LatticeKey(c), index);
    if (!inserted) {
      const Root& old = roots_[it->second];
      // Ties are pruned too: of two equally short ways into c, a turn that is taut for one
      // and not for the other can be shortcut, so it never lies on a shortest path.
      if (g >= old.g - kTol) return -1;
      it->second = index;
    }
    roots_.push_back(Root{c, parent, g});
    return index;
  }

  bool Superseded(int root) const {
    if (root == 0) return false;
    const Root& r = roots_[root];
    return roots_[best_root_.at(LatticeKey(r.p))].g < r.g - kTol;
  }

  void ExpandCone(const Node& n, const Root& r) {
    const int j = n.row;
    const double y = ys_[j];
    const int dir = y > r.p.y() ? 1 : -1;
    const int beyond = dir > 0 ? up_[j] : down_[j];
    const int behind = dir > 0 ? down_[j] : up_[j];
    const int next = j + dir;
    // Past the grid's edge: no free cell beyond, hence no convex corner on this row either.
    if (beyond < 0 || beyond >= grid_.height()) return;
    const double ratio = (ys_[next] - r.p.y()) / (y - r.p.y());
    const auto ray = [&](double x) { return r.p.x() + (x - r.p.x()) * ratio; };
    // Observable successors: the interval seen through each run of free cells beyond it.
    const AnyAngleGrid::Run* end = grid_.RunsEnd(beyond);
    const AnyAngleGrid::Run* run =
        std::lower_bound(grid_.RunsBegin(beyond), end, n.a - kTol,
                         [](const AnyAngleGrid::Run& run, double v) { return run.end < v; });
    for (; run != end && run->begin <= n.b + kTol; ++run) {
      const double a2 = std::max(n.a, static_cast<double>(run->begin));
      const double b2 = std::min(n.b, static_cast<double>(run->end));
      const bool touch_begin = b2 - a2 <= kTol && std::abs(b2 - run->begin) <= kTol;
      const bool touch_end = b2 - a2 <= kTol && std::abs(a2 - run->end) <= kTol;
      if (touch_begin || touch_end) {
        // The interval meets the run at one lattice point x0 only: just the vertical ray
        // passes, and only when one side of it stays free across the row.
        const int x0 = touch_begin ? run->begin : run->end;
        if (r.p.x() != x0) continue;
        const bool left = Free(x0 - 1, behind) && Free(x0 - 1, beyond);
        const bool right = Free(x0, behind) && Free(x0, beyond);
        if (left || right) Push(next, x0, x0, n.root);
        continue;
      }
      const double lo = std::max(ray(a2), static_cast<double>(run->begin));
      const double hi = std::min(ray(b2), static_cast<double>(run->end));
      if (lo <= hi + kTol) Push(next, lo, std::max(lo, hi), n.root);
    }
    TurnAtCorners(n, r, j, beyond, behind, next, ratio);
  }

  // Non-observable successors: around each convex corner of the interval, the part of the
  // next row (and of this row) that the root cannot see and a taut turn there reaches.
  void TurnAtCorners(const Node& n, const Root& r, int j, int beyond, int behind, int next,
                     double ratio) {
    if (!lattice_[j]) return;
    const double y = ys_[j];
    const int x_first = static_cast<int>(std::ceil(n.a - kTol));
    const int x_last = static_cast<int>(std::floor(n.b + kTol));
    RowChanges changes_beyond(grid_, beyond, x_first), changes_behind(grid_, behind, x_first);
    for (int x0 = NextChange(changes_beyond, changes_behind); x0 <= x_last;
         x0 = NextChange(changes_beyond, changes_behind)) {
      const bool ul = !Free(x0 - 1, beyond), ur = !Free(x0, beyond);
      const bool dl = !Free(x0 - 1, behind), dr = !Free(x0, behind);
      if (ul + ur + dl + dr != 1) continue;
      const double dx = x0 - r.p.x();
      const Point2 c(x0, y);
      const double ray = r.p.x() + dx * ratio;
      if (dr && dx >= 0) {
        const int root = NewRoot(c, n.root);
        if (root < 0) continue;
        const AnyAngleGrid::Run* run = grid_.RunAt(beyond, x0);
        Push(next, ray, run->end, root);
        Push(j, x0, ReachRight(j, x0), root);
      } else if (dl && dx <= 0) {
        const int root = NewRoot(c, n.root);
        if (root < 0) continue;
        const AnyAngleGrid::Run* run = grid_.RunAt(beyond, x0 - 1);
        Push(next, run->begin, ray, root);
        Push(j, ReachLeft(j, x0), x0, root);
      } else if (ul && dx > 0) {
        const int root = NewRoot(c, n.root);
        if (root < 0) continue;
        const AnyAngleGrid::Run* run = grid_.RunAt(beyond, x0);
        Push(next, x0, std::min(ray, static_cast<double>(run->end)), root);
      } else if (ur && dx < 0) {
        const int root = NewRoot(c, n.root);
        if (root < 0) continue;
        const AnyAngleGrid::Run* run = grid_.RunAt(beyond, x0 - 1);
        Push(next, std::max(ray, static_cast<double>(run->begin)), x0, root);
      }
    }
  }

  // A flat node runs along the root's own row: it turns into the row above or below at each
  // convex corner whose blocked cell it has just passed.
  void ExpandFlat(const Node& n, const Root& r) {
    const int j = n.row;
    if (!lattice_[j]) return;
    const double y = ys_[j];
    const bool rightward = n.b > r.p.x();
    const int x_first = static_cast<int>(std::ceil(n.a - kTol));
    const int x_last = static_cast<int>(std::floor(n.b + kTol));
    RowChanges changes_up(grid_, up_[j], x_first), changes_down(grid_, down_[j], x_first);
    for (int x0 = NextChange(changes_up, changes_down); x0 <= x_last;
         x0 = NextChange(changes_up, changes_down)) {
      if (x0 == r.p.x()) continue;
      const bool ul = !Free(x0 - 1, up_[j]), ur = !Free(x0, up_[j]);
      const bool dl = !Free(x0 - 1, down_[j]), dr = !Free(x0, down_[j]);
      if (ul + ur + dl + dr != 1) continue;
      const bool up = rightward ? ul : ur;
      const bool down = rightward ? dl : dr;
      if (!up && !down) continue;
      const int root = NewRoot(Point2(x0, y), n.root);
      if (root < 0) continue;
      const int band = up ? up_[j] : down_[j];
      const int next = up ? j + 1 : j - 1;
      const AnyAngleGrid::Run* run = grid_.RunAt(band, rightward ? x0 : x0 - 1);
      if (rightward) {
        Push(next, x0, run->end, root);
      } else {
        Push(next, run->begin, x0, root);
      }
    }
  }

  std::vector<Point2> PathTo(int root) const {
    std::vector<Point2> path = {goal_};
    for (int i = root; i >= 0; i = roots_[i].parent) path.push_back(roots_[i].p);
    std::reverse(path.begin(), path.end());
    return path;
  }

  const AnyAngleGrid& grid_;
  const Point2 start_, goal_;
  const StopToken* stop_;
  const int width_;
  std::vector<double> ys_;
  std::vector<int> up_, down_;
  std::vector<char> lattice_;
  int start_row_ = 0, goal_row_ = 0;
  std::vector<Root> roots_;
  std::vector<Node> nodes_;
  std::priority_queue<QueueEntry> open_;
  absl::flat_hash_map<int64_t, int> best_root_;
  int64_t expanded_ = 0;
};

}  // namespace

AnyAngleSearchResult AnyAngleSearch(const AnyAngleGrid& grid, const Point2& start,
                                    const Point2& goal, const StopToken* stop) {
  return Search(grid, start, goal, stop).Run();
}

}  // namespace swarmplan
