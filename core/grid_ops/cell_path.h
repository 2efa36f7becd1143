#pragma once

#include <optional>
#include <vector>

#include "core/graph/grid_search.h"
#include "core/grid_ops/grid_moves.h"
#include "core/map/point.h"
#include "core/random.h"

namespace swarmplan {

// Operators on paths of grid cells, shared by every grid planner.

// Cuts every loop: when a cell occurs again later in the path, everything after its first
// occurrence up to and including its last occurrence is removed. The result visits each cell
// once; consecutive cells of the result were consecutive in the input.
void RemoveLoops(std::vector<Cell>& cells);

// Whether every consecutive pair is a valid move under `moves` (and the path is non-empty).
bool IsValidCellPath(const GridMoves& moves, const std::vector<Cell>& cells);

// The A* options that produce moves valid under `moves`' rules (4- or 8-connected).
GridSearchOptions RepairSearchOptions(const GridMoves& moves);

// Makes the path connected: every consecutive pair that is not a valid move is joined by the
// interior cells of a shortest path (A*, core/graph). Repairs only the pairs at index >= `first`
// and < `last` (defaults: the whole path). False, with the path unchanged, when a gap cannot be
// joined.
bool RepairGaps(GridMoves& moves, std::vector<Cell>& cells, GridSearchContext* context,
                size_t first = 0, size_t last = static_cast<size_t>(-1));

// A path through the given cells in order, each leg a shortest path (A*), loops removed; nullopt
// when some leg has no path.
std::optional<std::vector<Cell>> JoinWithAStar(GridMoves& moves, const std::vector<Cell>& via,
                                               GridSearchContext* context);

// The usable cells reachable from `from` with 8- (or 4-, for that neighbourhood) connected moves
// under the rules: the cells a random feasible path may pass through.
std::vector<Cell> ReachableCells(GridMoves& moves, Cell from);

// A random feasible path: start -> 1..max_via random cells of `reachable` -> goal, joined by A*,
// loops removed (the AS-BFO and GA initial population). nullopt when start and goal are not
// connected.
std::optional<std::vector<Cell>> RandomFeasiblePath(GridMoves& moves, Cell start, Cell goal,
                                                    const std::vector<Cell>& reachable, int max_via,
                                                    Rng& rng, GridSearchContext* context);

}  // namespace swarmplan
