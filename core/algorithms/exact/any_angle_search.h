#pragma once

#include <cstdint>
#include <vector>

#include "core/algorithms/exact/any_angle_grid.h"
#include "core/map/point.h"
#include "core/stop_token.h"

namespace swarmplan {

struct AnyAngleSearchResult {
  bool found = false;
  bool stopped = false;
  // Grid coordinates ((world - origin) / resolution): the start, the convex corners the path
  // wraps, the goal.
  std::vector<Point2> vertices;
  double length = 0.0;  // in cells
  int64_t expanded = 0;
};

// The Euclidean shortest path between two points of the planning grid of `grid`, among its
// blocked cells (closed squares; the boundary of the grid bounds the map), never passing
// between two blocked cells that touch only at a corner. The path may touch blocked squares
// (it is the infimum of collision-free paths); OffsetTautPath makes it collision-free.
//
// The search is Anya (Harabor, Grastien, Oz, Aksakalli, JAIR 2016): nodes are an interval of
// one grid row and a root (the start or a convex corner) that sees every point of it; a node
// is expanded by projecting its interval through the next row of cells (same root) and by
// turning around the convex corners on it (new roots), with root-level pruning and the
// interval heuristic, so the first goal node popped is optimal. The rows through the start
// and the goal are added to the grid's rows, so the endpoints may be any points.
//
// `start` and `goal` must be inside the grid and touch no blocked cell (checked by the caller).
// `stop` (may be null) is checked every 4096 expansions.
AnyAngleSearchResult AnyAngleSearch(const AnyAngleGrid& grid, const Point2& start,
                                    const Point2& goal, const StopToken* stop);

}  // namespace swarmplan
