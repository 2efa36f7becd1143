#include "bench/papers/as_bfo_islands_check.h"

#include <cmath>
#include <cstdlib>
#include <string>

#include "absl/strings/str_cat.h"
#include "core/graph/grid_search.h"

namespace swarmplan::bench {
namespace {

constexpr double kTolerance = 1e-9;

std::string CellText(Cell c) { return absl::StrCat("(", c.x, ", ", c.y, ")"); }

// The cell whose centre `p` is; false when `p` is no cell centre.
bool CentreCell(const OccupancyGrid& grid, const Point3& p, Cell* cell) {
  *cell = grid.CellAt(Point2(p.x(), p.y()));
  return (grid.CellCenter(*cell) - Point2(p.x(), p.y())).norm() < 1e-6;
}

int Sign(int v) { return (v > 0) - (v < 0); }

}  // namespace

absl::Status CheckGridPath(const OccupancyGrid& grid, const Path& path, const PathMetrics& metrics,
                           Cell start, Cell goal, double optimum) {
  if (path.empty()) return absl::InternalError("found path is empty");
  std::vector<Cell> cells;
  for (size_t i = 0; i < path.size(); ++i) {
    Cell c;
    if (!CentreCell(grid, path[i], &c)) {
      return absl::InternalError(absl::StrCat("path point ", i, " is not a cell centre"));
    }
    cells.push_back(c);
  }
  if (cells.front() != start) {
    return absl::InternalError(
        absl::StrCat("path starts at ", CellText(cells.front()), ", not ", CellText(start)));
  }
  if (cells.back() != goal) {
    return absl::InternalError(
        absl::StrCat("path ends at ", CellText(cells.back()), ", not ", CellText(goal)));
  }
  for (size_t i = 0; i + 1 < cells.size(); ++i) {
    const int dx = cells[i + 1].x - cells[i].x;
    const int dy = cells[i + 1].y - cells[i].y;
    if ((dx == 0 && dy == 0) || (dx != 0 && dy != 0 && std::abs(dx) != std::abs(dy))) {
      return absl::InternalError(absl::StrCat("segment ", i, " from ", CellText(cells[i]), " to ",
                                              CellText(cells[i + 1]),
                                              " is not along one of the 8 grid directions"));
    }
    const Cell step{Sign(dx), Sign(dy)};
    for (Cell c = cells[i]; c != cells[i + 1];) {
      const Cell next{c.x + step.x, c.y + step.y};
      if (!GridMoveAllowed(grid, c, next)) {
        return absl::InternalError(absl::StrCat("move from ", CellText(c), " to ", CellText(next),
                                                " is blocked or cuts an obstacle corner"));
      }
      c = next;
    }
  }
  if (!metrics.collision_free) return absl::InternalError("path metrics: not collision-free");
  if (metrics.length < optimum - kTolerance) {
    return absl::InternalError(
        absl::StrCat("path length ", metrics.length, " is below the A* optimum ", optimum));
  }
  return absl::OkStatus();
}

}  // namespace swarmplan::bench
