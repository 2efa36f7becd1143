#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/map/map.h"
#include "core/map/occupancy_grid.h"

namespace swarmplan {

// Which side of the optimum with a clearance the planning grid's optimum lies on.
enum class ClearanceBound {
  kUpper,  // only cells that keep the clearance: its paths are feasible
  kLower,  // blocked only where a cell lies wholly closer than the clearance: never longer
};

// What the exact any-angle search needs of one (grid, clearance): the planning grid (the map's
// own grid for clearance 0, otherwise ClearanceGrid) and, per cell row, its maximal runs of
// free cells. Immutable; cached with the map (AnyAngleGridFor).
class AnyAngleGrid {
 public:
  // Free cells [begin, end) of one row; in grid coordinates the run covers x in [begin, end].
  struct Run {
    int begin;
    int end;
  };

  // `grid` must outlive the result when clearance is 0 (it is the planning grid then).
  static AnyAngleGrid Build(const OccupancyGrid& grid, double clearance,
                            ClearanceBound bound = ClearanceBound::kUpper);
  // Build(grid, clearance, bound) for a `grid` made from the grid of `base` (built with the same
  // clearance and bound) by blocking the `blocked` cells too: the base's planning grid measured
  // again only near those cells.
  static AnyAngleGrid BuildBlocking(const AnyAngleGrid& base, const OccupancyGrid& grid,
                                    const std::vector<Cell>& blocked, double clearance,
                                    ClearanceBound bound);

  // Same origin as the map's grid; its cells subdivide the map's cells when there is a clearance.
  const OccupancyGrid& planning_grid() const { return *planning_; }
  int width() const { return planning_->width(); }
  int height() const { return planning_->height(); }
  // Outside the grid (including row -1 and row height) counts as blocked.
  bool Blocked(int x, int y) const { return planning_->IsBlocked(x, y); }
  // The runs of cell row y, sorted by x; empty outside the grid.
  const Run* RunsBegin(int y) const;
  const Run* RunsEnd(int y) const;
  // The run of row y holding cell x, or nullptr when that cell is blocked.
  const Run* RunAt(int y, int x) const;
  // Bytes held by the runs and, with a clearance, the planning grid.
  int64_t MemoryBytes() const;

 private:
  static AnyAngleGrid OnPlanningGrid(std::shared_ptr<const OccupancyGrid> subdivided);
  void FindRuns();  // of planning_
  void AppendRunsOfRow(int y);

  std::shared_ptr<const OccupancyGrid> subdivided_;  // null when the clearance is 0
  const OccupancyGrid* planning_ = nullptr;
  std::vector<Run> runs_;
  std::vector<int> row_start_;  // height + 1 offsets into runs_
};

// Map cells per axis of the planning grid's cells for a clearance: 4 while the subdivided grid
// stays within kMaxSubdividedCells, else 2, else 1.
int ClearanceSubdivision(const OccupancyGrid& grid);
inline constexpr int64_t kMaxSubdividedCells = 4LL * 1024 * 1024;

// The grid a robot of radius `clearance` (world units, > 0) plans on: every cell of `grid`
// split into ClearanceSubdivision(grid)^2 cells. kUpper blocks a cell whose closed square comes
// closer than the clearance to a blocked square of `grid`, so every point of a free cell keeps
// the clearance; kLower blocks a cell only when its centre lies closer than the clearance minus
// half its diagonal (or inside a blocked square), so every point that keeps the clearance lies
// in a free cell. Shortest paths on the two bracket the optimum with the clearance; the gap
// shrinks with the cell size. The map's edge is no obstacle.
OccupancyGrid ClearanceGrid(const OccupancyGrid& grid, double clearance, ClearanceBound bound);

// ClearanceGrid(grid, clearance, bound) for a `grid` made from another by blocking the `blocked`
// cells too, from that other grid's ClearanceGrid `base` (same clearance and bound): the same
// cells, measured only near the newly blocked ones.
OccupancyGrid ClearanceGridBlocking(const OccupancyGrid& base, const OccupancyGrid& grid,
                                    const std::vector<Cell>& blocked, double clearance,
                                    ClearanceBound bound);

// The cached AnyAngleGrid of a grid map for `clearance` (built on first use, shared by jobs);
// for a map with a GridPatch, from its base map's.
std::shared_ptr<const AnyAngleGrid> AnyAngleGridFor(const Map& map, double clearance,
                                                    ClearanceBound bound = ClearanceBound::kUpper);

}  // namespace swarmplan
