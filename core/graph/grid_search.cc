#include "core/graph/grid_search.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace swarmplan {
namespace {

constexpr double kSqrt2 = 1.41421356237309504880;
constexpr double kHalfDiagonal = kSqrt2 / 2;

struct Step {
  int dx;
  int dy;
};
// Fixed neighbour order: part of the deterministic tie-breaking.
constexpr Step kOrthogonalSteps[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
constexpr Step kDiagonalSteps[] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}};

// Distance in cells from a cell centre to the square of a cell offset by (dx, dy) cells.
double CenterToSquare(int dx, int dy) {
  const double gx = std::max(std::abs(dx) - 0.5, 0.0);
  const double gy = std::max(std::abs(dy) - 0.5, 0.0);
  return std::hypot(gx, gy);
}

}  // namespace

void GridSearchContext::Begin(size_t cell_count, bool with_clearance) {
  if (nodes_.size() < cell_count) nodes_.resize(cell_count, Node{0.0, -1, 0});
  if (with_clearance && usable_known_.size() < cell_count) {
    usable_known_.resize(cell_count, 0);
    usable_.resize(cell_count);
  }
  generation_ += 2;
  if (generation_ < 2) {  // wrapped: old stamps could collide with new generations
    for (Node& n : nodes_) n.stamp = 0;
    std::fill(usable_known_.begin(), usable_known_.end(), 0);
    generation_ = 2;
  }
  open_.clear();
}

namespace {

// CellCenterClearance of an unblocked cell whose distance-field value is `d`.
double CenterClearanceFrom(const OccupancyGrid& grid, Cell cell, double d) {
  if (!std::isfinite(d)) return d;
  const double r = grid.resolution();
  // The nearest blocked centre is d away, so the nearest square is at most d - r/2 away, and
  // every square within that distance has its centre within d - r/2 + r*sqrt(2)/2 < d + r.
  const int k = static_cast<int>(std::ceil(d / r)) + 1;
  double best = std::numeric_limits<double>::infinity();
  const int y0 = std::max(cell.y - k, 0), y1 = std::min(cell.y + k, grid.height() - 1);
  const int x0 = std::max(cell.x - k, 0), x1 = std::min(cell.x + k, grid.width() - 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (grid.IsBlocked(x, y)) best = std::min(best, CenterToSquare(x - cell.x, y - cell.y));
    }
  }
  return best * r;
}

// CellUsable of an unblocked cell inside the grid whose distance-field value is `d`, for a
// positive clearance.
bool UsableFrom(const OccupancyGrid& grid, Cell cell, double clearance, double d) {
  const double r = grid.resolution();
  // The nearest blocked square is between d - r*sqrt(2)/2 and d - r/2 away.
  if (d - r * kHalfDiagonal >= clearance) return true;
  if (d - r / 2 < clearance) return false;
  return CenterClearanceFrom(grid, cell, d) >= clearance;
}

// The distance field's value at `cell` (world units) when some blocked cell centre lies within
// `limit` of the cell's centre, found by scanning square rings outwards; otherwise a value above
// `limit` (+infinity when no blocked cell lies within the scanned rings).
double LocalDistanceToObstacle(const OccupancyGrid& grid, Cell cell, double limit) {
  const double r = grid.resolution();
  const double rings = std::min(std::floor(limit / r) + 1.0,
                                static_cast<double>(std::max(grid.width(), grid.height())));
  int64_t best = -1;  // squared distance in cells to the nearest blocked centre seen
  auto visit = [&](int x, int y) {
    if (!grid.IsBlocked(x, y)) return;
    const int64_t dx = x - cell.x, dy = y - cell.y;
    const int64_t squared = dx * dx + dy * dy;
    if (best < 0 || squared < best) best = squared;
  };
  for (int k = 1; k <= static_cast<int>(rings); ++k) {
    // Every cell of ring k is at least k cells away.
    if (best >= 0 && best <= static_cast<int64_t>(k) * k) break;
    const int x0 = std::max(cell.x - k, 0), x1 = std::min(cell.x + k, grid.width() - 1);
    const int y0 = std::max(cell.y - k + 1, 0), y1 = std::min(cell.y + k - 1, grid.height() - 1);
    // The ring's sides that lie inside the grid.
    const bool bottom = cell.y - k >= 0, top = cell.y + k < grid.height();
    const bool left = cell.x - k >= 0, right = cell.x + k < grid.width();
    if (!bottom && !top && !left && !right) break;
    for (int x = x0; x <= x1; ++x) {
      if (bottom) visit(x, cell.y - k);
      if (top) visit(x, cell.y + k);
    }
    for (int y = y0; y <= y1; ++y) {
      if (left) visit(cell.x - k, y);
      if (right) visit(cell.x + k, y);
    }
  }
  if (best < 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(static_cast<double>(best)) * r;
}

}  // namespace

double CellCenterClearance(const OccupancyGrid& grid, Cell cell) {
  if (grid.IsBlocked(cell)) return 0.0;
  return CenterClearanceFrom(grid, cell, grid.DistanceToObstacle(cell.x, cell.y));
}

bool CellUsable(const OccupancyGrid& grid, Cell cell, double clearance) {
  if (!grid.InBounds(cell) || grid.IsBlocked(cell)) return false;
  if (clearance <= 0) return true;
  return UsableFrom(grid, cell, clearance, grid.DistanceToObstacle(cell.x, cell.y));
}

bool CellUsableWithoutField(const OccupancyGrid& grid, Cell cell, double clearance) {
  if (!grid.InBounds(cell) || grid.IsBlocked(cell)) return false;
  if (clearance <= 0) return true;
  // Beyond this distance of the nearest blocked centre a cell is usable whatever the value.
  const double limit = clearance + grid.resolution() * kHalfDiagonal;
  return UsableFrom(grid, cell, clearance, LocalDistanceToObstacle(grid, cell, limit));
}

bool GridMoveAllowed(const OccupancyGrid& grid, Cell from, Cell to,
                     const GridSearchOptions& options) {
  const int dx = to.x - from.x, dy = to.y - from.y;
  if (std::max(std::abs(dx), std::abs(dy)) != 1) return false;
  const double c = options.clearance;
  if (!CellUsable(grid, from, c) || !CellUsable(grid, to, c)) return false;
  if (dx == 0 || dy == 0) return true;
  if (options.connectivity == GridConnectivity::kFour) return false;
  return options.allow_corner_cutting || (CellUsable(grid, Cell{from.x + dx, from.y}, c) &&
                                          CellUsable(grid, Cell{from.x, from.y + dy}, c));
}

double CellPathLength(const OccupancyGrid& grid, const std::vector<Cell>& cells) {
  // Orthogonal and diagonal steps are counted apart so that equal paths give equal lengths.
  int64_t orthogonal = 0, diagonal = 0;
  double other = 0.0;
  for (size_t i = 1; i < cells.size(); ++i) {
    const int dx = std::abs(cells[i].x - cells[i - 1].x);
    const int dy = std::abs(cells[i].y - cells[i - 1].y);
    if ((dx == 1 && dy == 0) || (dx == 0 && dy == 1)) {
      ++orthogonal;
    } else if (dx == 1 && dy == 1) {
      ++diagonal;
    } else {
      other += std::hypot(dx, dy);
    }
  }
  return (static_cast<double>(orthogonal) + kSqrt2 * static_cast<double>(diagonal) + other) *
         grid.resolution();
}

Path CellPathToWorld(const OccupancyGrid& grid, const std::vector<Cell>& cells) {
  Path path;
  path.reserve(cells.size());
  for (const Cell& c : cells) {
    const Point2 p = grid.CellCenter(c);
    path.emplace_back(p.x(), p.y(), 0.0);
  }
  return path;
}

// One search over a context's arrays.
class GridSearcher {
 public:
  // `line_of_sight` null: A*/Dijkstra; otherwise Theta*.
  GridSearcher(const OccupancyGrid& grid, const GridSearchOptions& options,
               const LineOfSight* line_of_sight, GridSearchContext& context)
      : grid_(grid),
        options_(options),
        line_of_sight_(line_of_sight),
        ctx_(context),
        width_(grid.width()) {}

  GridSearchResult Run(Cell from, Cell to) {
    GridSearchResult result;
    ctx_.Begin(static_cast<size_t>(grid_.width()) * grid_.height(), options_.clearance > 0);
    reached_ = ctx_.generation_;
    closed_ = reached_ + 1;
    if (!Usable(from.x, from.y) || !Usable(to.x, to.y)) return result;
    goal_ = to;
    const int32_t start = Index(from.x, from.y);
    const int32_t goal = Index(to.x, to.y);
    Reach(start, -1, 0.0, from.x, from.y);

    const bool eight = options_.connectivity == GridConnectivity::kEight;
    const double r = grid_.resolution();
    const double diagonal_cost = kSqrt2 * r;
    while (!ctx_.open_.empty()) {
      std::pop_heap(ctx_.open_.begin(), ctx_.open_.end(), Lower{});
      const int32_t i = ctx_.open_.back().index;
      ctx_.open_.pop_back();
      GridSearchContext::Node& node = ctx_.nodes_[i];
      // A node is pushed again whenever its g improves; only its best (first) entry counts.
      if (node.stamp == closed_) continue;
      node.stamp = closed_;
      ++result.expanded;
      if (i == goal) break;
      if (ShouldStop(result.expanded)) {
        result.stopped = true;
        return result;
      }
      const int x = i % width_, y = i / width_;
      const double g = node.g;
      bool open_side[4];  // usable orthogonal neighbours, in kOrthogonalSteps order
      for (int k = 0; k < 4; ++k) {
        const int nx = x + kOrthogonalSteps[k].dx, ny = y + kOrthogonalSteps[k].dy;
        open_side[k] = Usable(nx, ny);
        if (open_side[k]) Relax(i, g + r, nx, ny);
      }
      if (!eight) continue;
      for (int k = 0; k < 4; ++k) {
        const Step& s = kDiagonalSteps[k];
        const bool sides = open_side[s.dx > 0 ? 0 : 1] && open_side[s.dy > 0 ? 2 : 3];
        if (!sides && !options_.allow_corner_cutting) continue;
        const int nx = x + s.dx, ny = y + s.dy;
        if (Usable(nx, ny)) Relax(i, g + diagonal_cost, nx, ny);
      }
    }
    if (ctx_.nodes_[goal].stamp != closed_) return result;
    for (int32_t i = goal; i != -1; i = ctx_.nodes_[i].parent) {
      result.cells.push_back(Cell{i % width_, i / width_});
    }
    std::reverse(result.cells.begin(), result.cells.end());
    result.found = true;
    result.length = CellPathLength(grid_, result.cells);
    return result;
  }

 private:
  // Heap order: smallest f first; among equal f the larger g (deeper node), then the smaller
  // index. std::*_heap keep the largest element on top, so this is "a ranks below b". A type
  // rather than a function so the heap operations inline it.
  struct Lower {
    bool operator()(const GridSearchContext::OpenEntry& a,
                    const GridSearchContext::OpenEntry& b) const {
      if (a.f != b.f) return a.f > b.f;
      if (a.g != b.g) return a.g < b.g;
      return a.index > b.index;
    }
  };

  int32_t Index(int x, int y) const { return y * width_ + x; }

  bool Usable(int x, int y) {
    if (!grid_.InBounds(x, y)) return false;
    if (options_.clearance <= 0) return !grid_.IsBlocked(x, y);
    const int32_t i = Index(x, y);
    if (ctx_.usable_known_[i] != reached_) {
      ctx_.usable_[i] = CellUsable(grid_, Cell{x, y}, options_.clearance) ? 1 : 0;
      ctx_.usable_known_[i] = reached_;
    }
    return ctx_.usable_[i] != 0;
  }

  double Heuristic(int x, int y) const {
    if (!options_.use_heuristic) return 0.0;
    const int dx = std::abs(x - goal_.x), dy = std::abs(y - goal_.y);
    if (line_of_sight_ != nullptr) return std::hypot(dx, dy) * grid_.resolution();
    if (options_.connectivity == GridConnectivity::kFour) {
      return static_cast<double>(dx + dy) * grid_.resolution();
    }
    const int lo = std::min(dx, dy), hi = std::max(dx, dy);
    return (static_cast<double>(hi - lo) + kSqrt2 * lo) * grid_.resolution();
  }

  void Reach(int32_t i, int32_t parent, double g, int x, int y) {
    ctx_.nodes_[i] = GridSearchContext::Node{g, parent, reached_};
    ctx_.open_.push_back({g + Heuristic(x, y), static_cast<float>(g), i});
    std::push_heap(ctx_.open_.begin(), ctx_.open_.end(), Lower{});
  }

  void Relax(int32_t from, double g, int x, int y) {
    const int32_t j = Index(x, y);
    const GridSearchContext::Node& node = ctx_.nodes_[j];
    if (node.stamp == closed_) return;
    if (line_of_sight_ != nullptr) {
      const int32_t p = ctx_.nodes_[from].parent;
      if (p != -1) {
        const Cell pc{p % width_, p / width_};
        if ((*line_of_sight_)(pc, Cell{x, y})) {
          from = p;
          g = ctx_.nodes_[p].g + std::hypot(x - pc.x, y - pc.y) * grid_.resolution();
        }
      }
    }
    if (node.stamp == reached_ && node.g <= g) return;
    Reach(j, from, g, x, y);
  }

  bool ShouldStop(int64_t expanded) const {
    if (options_.max_expansions > 0 && expanded >= options_.max_expansions) return true;
    return options_.stop != nullptr && expanded % kStopCheckInterval == 0 &&
           options_.stop->Check(0) != StopReason::kNone;
  }

  const OccupancyGrid& grid_;
  const GridSearchOptions& options_;
  const LineOfSight* line_of_sight_;
  GridSearchContext& ctx_;
  const int width_;
  uint32_t reached_ = 0;  // node stamps of this search
  uint32_t closed_ = 0;
  Cell goal_;
};

GridSearchResult SearchGrid(const OccupancyGrid& grid, Cell from, Cell to,
                            const GridSearchOptions& options, GridSearchContext* context) {
  GridSearchContext local;
  GridSearcher searcher(grid, options, nullptr, context != nullptr ? *context : local);
  return searcher.Run(from, to);
}

GridSearchResult SearchGridAnyAngle(const OccupancyGrid& grid, Cell from, Cell to,
                                    const GridSearchOptions& options,
                                    const LineOfSight& line_of_sight, GridSearchContext* context) {
  GridSearchContext local;
  GridSearcher searcher(grid, options, &line_of_sight, context != nullptr ? *context : local);
  return searcher.Run(from, to);
}

std::optional<std::vector<Cell>> AStarCells(const OccupancyGrid& grid, Cell from, Cell to,
                                            const GridSearchOptions& options,
                                            GridSearchContext* context) {
  GridSearchResult result = SearchGrid(grid, from, to, options, context);
  if (!result.found) return std::nullopt;
  return std::move(result.cells);
}

}  // namespace swarmplan
