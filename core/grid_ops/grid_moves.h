#pragma once

#include <cstdint>
#include <vector>

#include "core/map/occupancy_grid.h"
#include "core/map/point.h"

namespace swarmplan {

// Which cells a grid planner may step to from a cell: the 4 orthogonal neighbours, the 8
// neighbours, or the 24 cells within Chebyshev distance 2 (16 directions, step lengths 1 ... 2√2).
enum class Neighbourhood { k4 = 4, k8 = 8, k24 = 24 };

// The offsets (dx, dy) of a neighbourhood, in a fixed order.
const std::vector<Cell>& MoveOffsets(Neighbourhood neighbourhood);

// The cells whose closed square the segment between the centres of a and b touches (corners
// included), in no particular order.
std::vector<Cell> CellsTouchedBySegment(Cell a, Cell b);

// Distance between the segment [a, b] and the axis-aligned box [lo, hi] (0 when they meet).
double SegmentBoxDistance(const Point2& a, const Point2& b, const Point2& lo, const Point2& hi);

struct MoveRules {
  Neighbourhood neighbourhood = Neighbourhood::k8;
  // false: a move is valid only when the segment between the cell centres touches no unusable
  // cell (corners included). true: only the two end cells must be usable ("jumping").
  bool segment_check = true;
  double clearance = 0.0;  // world units; a cell is usable per CellUsable (core/graph)
};

// The moves of one grid under one set of rules. The valid moves out of a cell are computed once,
// when first asked for, and shared by every caller (the fish swarm paper's sharing mechanism).
// Not thread-safe: one instance per search.
class GridMoves {
 public:
  GridMoves(const OccupancyGrid& grid, MoveRules rules);

  const OccupancyGrid& grid() const { return *grid_; }
  const MoveRules& rules() const { return rules_; }
  bool Usable(Cell c) const { return grid_->InBounds(c) && usable_[Index(c)] != 0; }
  // Whether `from` -> `to` is a move of the neighbourhood and valid under the rules.
  bool IsMove(Cell from, Cell to) const;
  // Whether the straight step between two cells (any distance) is valid under the rules,
  // ignoring the neighbourhood.
  bool StepValid(Cell from, Cell to) const;
  // The cells reachable by one valid move from `from` (empty for an unusable cell).
  const std::vector<Cell>& ValidMoves(Cell from);
  int64_t cells_computed() const { return cells_computed_; }

 private:
  size_t Index(Cell c) const { return static_cast<size_t>(c.y) * grid_->width() + c.x; }

  const OccupancyGrid* grid_;
  MoveRules rules_;
  std::vector<uint8_t> usable_;
  std::vector<std::vector<Cell>> moves_;
  std::vector<uint8_t> moves_known_;
  int64_t cells_computed_ = 0;
};

}  // namespace swarmplan
