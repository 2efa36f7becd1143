#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/map/map.h"
#include "core/map/occupancy_grid.h"

namespace swarmplan {

// What the exact any-angle search needs of one (grid, clearance): the planning grid (the map's
// own grid for clearance 0, otherwise the grid inflated by the clearance) and, per cell row,
// its maximal runs of free cells. Immutable; cached with the map (AnyAngleGridFor).
class AnyAngleGrid {
 public:
  // Free cells [begin, end) of one row; in grid coordinates the run covers x in [begin, end].
  struct Run {
    int begin;
    int end;
  };

  // `grid` must outlive the result when clearance is 0 (it is the planning grid then).
  static AnyAngleGrid Build(const OccupancyGrid& grid, double clearance);

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
  // Bytes held by the runs and, when inflated, the inflated grid.
  int64_t MemoryBytes() const;

 private:
  std::shared_ptr<const OccupancyGrid> inflated_;  // null when the clearance is 0
  const OccupancyGrid* planning_ = nullptr;
  std::vector<Run> runs_;
  std::vector<int> row_start_;  // height + 1 offsets into runs_
};

// The cells of `grid` a robot of radius `clearance` (world units) may occupy: a cell is blocked
// when its closed square comes closer than clearance + resolution / 16 to a blocked square (the
// sixteenth keeps paths along the inflated boundary acceptable to the grid collision checker,
// whose clearance test may be that much pessimistic). Cells outside keep their own state.
OccupancyGrid InflateGrid(const OccupancyGrid& grid, double clearance);

// The cached AnyAngleGrid of a grid map for `clearance` (built on first use, shared by jobs).
std::shared_ptr<const AnyAngleGrid> AnyAngleGridFor(const Map& map, double clearance);

}  // namespace swarmplan
