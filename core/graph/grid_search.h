#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/map/occupancy_grid.h"
#include "core/map/point.h"
#include "core/stop_token.h"

namespace swarmplan {

// Exact shortest paths between cells of an OccupancyGrid: A* (octile or Manhattan heuristic) and
// Dijkstra. Moves go to the 4 or 8 neighbouring cells; an orthogonal step costs one resolution,
// a diagonal step sqrt(2) resolutions (octile costs, the Moving AI convention).
//
// Usable cells. With clearance 0 a cell is usable when it is free. With clearance c > 0 a cell
// is usable when its centre is at least c (world units) from every blocked cell square (the
// whole square of the cell, not its centre); cells outside the grid do not count as obstacles,
// but a path never leaves the grid.
//
// Corner cutting. By default a diagonal step is allowed only when both orthogonal neighbours it
// passes between are usable too. Then every point of the polyline through the cell centres keeps
// the clearance, not only its vertices: an orthogonal step is closest to any square at one of its
// ends, and a diagonal step is never closer to a square than the nearest of the four centres
// around it. With `allow_corner_cutting` only the two end cells must be usable, so the path may
// touch a blocked corner (and, for c > 0, come closer than c between the centres).

enum class GridConnectivity { kFour, kEight };

struct GridSearchOptions {
  GridConnectivity connectivity = GridConnectivity::kEight;
  bool allow_corner_cutting = false;
  double clearance = 0.0;  // world units, >= 0
  // false: Dijkstra (no heuristic); true: A* with the octile (8) or Manhattan (4) distance,
  // the obstacle-free path length, so consistent (Euclidean in the any-angle search).
  bool use_heuristic = true;
  // Optional: checked every few thousand expansions (cancellation and deadline only).
  const StopToken* stop = nullptr;
  // 0: unlimited. The search gives up (found = false) after this many expansions.
  int64_t max_expansions = 0;
};

struct GridSearchResult {
  bool found = false;
  bool stopped = false;     // the stop token or max_expansions ended the search early
  std::vector<Cell> cells;  // from start to goal, inclusive; empty when not found
  double length = 0.0;      // world units
  int64_t expanded = 0;     // nodes taken off the open list
};

// Reusable search memory: generation-stamped arrays sized to the largest grid seen, so repeated
// searches do not allocate or clear per search. One context per thread; not thread-safe.
class GridSearchContext {
 public:
  GridSearchContext() = default;

 private:
  friend class GridSearcher;
  struct OpenEntry {
    double f;
    float g;  // only breaks ties between equal f; 16-byte entries keep the heap fast
    int32_t index;
  };
  void Begin(size_t cell_count, bool with_clearance);

  struct Node {
    double g;
    int32_t parent;
    uint32_t stamp;  // generation_: reached (g, parent valid); generation_ + 1: expanded
  };
  uint32_t generation_ = 0;  // advances by 2 per search
  std::vector<Node> nodes_;
  std::vector<uint32_t> usable_known_;  // == generation_: usable_ is valid (clearance > 0)
  std::vector<uint8_t> usable_;
  std::vector<OpenEntry> open_;
};

// Whether the straight segment between two usable cell centres is clear, for any-angle search.
using LineOfSight = std::function<bool(Cell from, Cell to)>;

// Shortest path from `from` to `to`. Not found (found = false, empty cells) when either end is
// not usable or no path exists. `context` may be null (a temporary one is used).
GridSearchResult SearchGrid(const OccupancyGrid& grid, Cell from, Cell to,
                            const GridSearchOptions& options = {},
                            GridSearchContext* context = nullptr);

// Basic Theta* (Nash, Daniel, Koenig & Felner 2007) over the same moves as SearchGrid: when a
// node's parent can see a neighbour, the neighbour may take that parent directly (any-angle),
// with Euclidean costs and heuristic. `cells` are then the path's turning cells, not neighbours.
// See theta_star.h for the form that checks line of sight with a CollisionChecker.
GridSearchResult SearchGridAnyAngle(const OccupancyGrid& grid, Cell from, Cell to,
                                    const GridSearchOptions& options,
                                    const LineOfSight& line_of_sight,
                                    GridSearchContext* context = nullptr);

// The cells of a shortest path, or nullopt: the component form other planners use (e.g. to
// repair a gap between two cells of a path).
std::optional<std::vector<Cell>> AStarCells(const OccupancyGrid& grid, Cell from, Cell to,
                                            const GridSearchOptions& options = {},
                                            GridSearchContext* context = nullptr);

// Distance in world units from the centre of `cell` to the nearest blocked cell square (0 on a
// blocked cell, +infinity when nothing is blocked). Exact; uses the grid's distance field and
// scans a neighbourhood only when the field's bounds do not decide.
double CellCenterClearance(const OccupancyGrid& grid, Cell cell);

// Whether `cell` is inside the grid and usable for `clearance` (see above).
bool CellUsable(const OccupancyGrid& grid, Cell cell, double clearance);
// The same verdict from the cells within about `clearance` of `cell`, without the grid's
// distance field: for checking a few cells (a request's start and goal) of a grid whose field
// may never be needed.
bool CellUsableWithoutField(const OccupancyGrid& grid, Cell cell, double clearance);

// Whether a single move between neighbouring cells (Chebyshev distance 1) is allowed under the
// options' rules: both ends usable and, for a diagonal without corner cutting, both orthogonal
// neighbours usable. 4-connectivity forbids diagonals. Ignores use_heuristic and stop.
bool GridMoveAllowed(const OccupancyGrid& grid, Cell from, Cell to,
                     const GridSearchOptions& options = {});

// Length in world units of a cell path (octile step costs; any step is measured as the straight
// segment between the centres).
double CellPathLength(const OccupancyGrid& grid, const std::vector<Cell>& cells);

// Cell centres in world coordinates, z = 0.
Path CellPathToWorld(const OccupancyGrid& grid, const std::vector<Cell>& cells);

}  // namespace swarmplan
