#include "core/grid_ops/cell_path.h"

#include <deque>

#include "absl/container/flat_hash_map.h"

namespace swarmplan {

void RemoveLoops(std::vector<Cell>& cells) {
  absl::flat_hash_map<int64_t, size_t> last;
  last.reserve(cells.size());
  for (size_t i = 0; i < cells.size(); ++i) last[CellKey(cells[i])] = i;
  std::vector<Cell> out;
  out.reserve(cells.size());
  for (size_t i = 0; i < cells.size(); i = last[CellKey(cells[i])] + 1) out.push_back(cells[i]);
  cells = std::move(out);
}

bool IsValidCellPath(const GridMoves& moves, const std::vector<Cell>& cells) {
  if (cells.empty() || !moves.Usable(cells.front())) return false;
  for (size_t i = 1; i < cells.size(); ++i) {
    if (!moves.IsMove(cells[i - 1], cells[i])) return false;
  }
  return true;
}

GridSearchOptions RepairSearchOptions(const GridMoves& moves) {
  GridSearchOptions options;
  options.connectivity = moves.rules().neighbourhood == Neighbourhood::k4
                             ? GridConnectivity::kFour
                             : GridConnectivity::kEight;
  options.allow_corner_cutting = !moves.rules().segment_check;
  options.clearance = moves.rules().clearance;
  return options;
}

bool RepairGaps(GridMoves& moves, std::vector<Cell>& cells, GridSearchContext* context,
                size_t first, size_t last) {
  if (cells.size() < 2) return true;
  last = std::min(last, cells.size() - 1);
  const GridSearchOptions options = RepairSearchOptions(moves);
  std::vector<Cell> out;
  out.reserve(cells.size() + 8);
  out.push_back(cells[0]);
  for (size_t i = 1; i < cells.size(); ++i) {
    const size_t pair = i - 1;
    if (pair >= first && pair < last && !moves.IsMove(cells[i - 1], cells[i])) {
      std::optional<std::vector<Cell>> leg =
          AStarCells(moves.grid(), cells[i - 1], cells[i], options, context);
      if (!leg || leg->size() < 2) return false;
      out.insert(out.end(), leg->begin() + 1, leg->end() - 1);
    }
    out.push_back(cells[i]);
  }
  cells = std::move(out);
  return true;
}

std::optional<std::vector<Cell>> JoinWithAStar(GridMoves& moves, const std::vector<Cell>& via,
                                               GridSearchContext* context) {
  if (via.empty()) return std::nullopt;
  const GridSearchOptions options = RepairSearchOptions(moves);
  std::vector<Cell> path{via.front()};
  for (size_t i = 1; i < via.size(); ++i) {
    if (via[i] == via[i - 1]) continue;
    std::optional<std::vector<Cell>> leg =
        AStarCells(moves.grid(), via[i - 1], via[i], options, context);
    if (!leg || leg->empty()) return std::nullopt;
    path.insert(path.end(), leg->begin() + 1, leg->end());
  }
  RemoveLoops(path);
  return path;
}

std::vector<Cell> ReachableCells(GridMoves& moves, Cell from) {
  std::vector<Cell> out;
  if (!moves.Usable(from)) return out;
  const OccupancyGrid& grid = moves.grid();
  std::vector<uint8_t> seen(static_cast<size_t>(grid.width()) * grid.height(), 0);
  const GridSearchOptions options = RepairSearchOptions(moves);
  const std::vector<Cell>& offsets = MoveOffsets(
      options.connectivity == GridConnectivity::kFour ? Neighbourhood::k4 : Neighbourhood::k8);
  std::deque<Cell> queue{from};
  seen[static_cast<size_t>(from.y) * grid.width() + from.x] = 1;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    out.push_back(c);
    for (const Cell& d : offsets) {
      const Cell n{c.x + d.x, c.y + d.y};
      if (!grid.InBounds(n)) continue;
      uint8_t& s = seen[static_cast<size_t>(n.y) * grid.width() + n.x];
      if (s || !GridMoveAllowed(grid, c, n, options)) continue;
      s = 1;
      queue.push_back(n);
    }
  }
  return out;
}

std::optional<std::vector<Cell>> RandomFeasiblePath(GridMoves& moves, Cell start, Cell goal,
                                                    const std::vector<Cell>& reachable, int max_via,
                                                    Rng& rng, GridSearchContext* context) {
  if (reachable.empty()) return std::nullopt;
  std::vector<Cell> via{start};
  const int count = max_via > 0 ? static_cast<int>(rng.UniformInt(1, max_via)) : 0;
  for (int i = 0; i < count; ++i) {
    via.push_back(reachable[rng.UniformInt(0, static_cast<int64_t>(reachable.size()) - 1)]);
  }
  via.push_back(goal);
  return JoinWithAStar(moves, via, context);
}

}  // namespace swarmplan
