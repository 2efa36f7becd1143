#pragma once

#include "core/geometry/collision.h"
#include "core/map/occupancy_grid.h"

namespace swarmplan {

// Collision checking on an occupancy grid. The map is the closed rectangle the cells cover;
// obstacles are the closed squares of blocked cells. Allocation-free; the grid must outlive
// the checker.
class GridCollisionChecker final : public CollisionChecker {
 public:
  explicit GridCollisionChecker(const OccupancyGrid& grid);

  // Distance to the nearest blocked square: exact when that square is within a few cells,
  // otherwise a lower bound from the distance field that is at most resolution * sqrt(2)
  // below the truth. Negative inside a blocked cell (minus the depth in that cell, at least
  // 1e-9 cells), +infinity when nothing is blocked.
  double Clearance(const Point3& p) const override;
  // Exact distance from the segment to the nearest blocked square (a == b: from the point).
  // When the segment meets a blocked square: 0, or negative when sphere tracing finds it inside
  // one (then about minus its depth there). +infinity when nothing is blocked.
  double SegmentClearance(const Point3& a, const Point3& b) const override;
  // clearance <= 0: exact cell traversal (every cell whose closed square meets the segment
  // must be free). clearance > 0: sphere tracing accepts what it can prove free; the rest is
  // decided by the exact distance, so the answer is exact either way.
  bool SegmentFree(const Point3& a, const Point3& b, double clearance) const override;

  // SegmentFree's verdict from a scan of every cell within `clearance` of the segment's box (an
  // exact segment-square distance per blocked cell): cheaper than tracing for segments of a cell
  // or so near obstacles, as the fitness engine's are; the cost grows with the box's area.
  bool SegmentFreeByScan(const Point3& a, const Point3& b, double clearance) const;

  // True when every cell whose closed square meets the segment is free (a and b in grid
  // coordinates, i.e. (world - origin) / resolution). Exposed for tests and grid planners.
  bool TraversalFree(const Point2& a, const Point2& b) const;

 private:
  bool InMap(const Point2& local) const;
  // TraversalFree's verdict when it is true and the segment's box holds a few cells: all of
  // them free. False when some is blocked or the box is larger.
  bool ShortSegmentBoxFree(const Point2& a, const Point2& b) const;
  // Clearance at a point given in grid coordinates, in cells.
  double LocalClearance(const Point2& local) const;
  // Smallest clearance along a..b (grid coordinates, in cells) while it stays >= floor;
  // returns a value below floor as soon as one is found.
  double TraceClearance(const Point2& a, const Point2& b, double floor) const;
  // Exact distance (cells) from a..b (grid coordinates) to the nearest blocked square when it
  // is below `bound`; otherwise some value >= bound. With stop_below_bound, returns as soon
  // as any square closer than `bound` is found (a value < bound, not necessarily the least).
  double SquareDistance(const Point2& a, const Point2& b, double bound,
                        bool stop_below_bound) const;

  const OccupancyGrid& grid_;
  double inv_resolution_;
};

}  // namespace swarmplan
