#include "core/graph/theta_star.h"

namespace swarmplan {

GridSearchResult ThetaStar(const OccupancyGrid& grid, const CollisionChecker& checker, Cell from,
                           Cell to, const GridSearchOptions& options, GridSearchContext* context) {
  const LineOfSight line_of_sight = [&](Cell a, Cell b) {
    const Point2 pa = grid.CellCenter(a), pb = grid.CellCenter(b);
    return checker.SegmentFree(Point3(pa.x(), pa.y(), 0.0), Point3(pb.x(), pb.y(), 0.0),
                               options.clearance);
  };
  return SearchGridAnyAngle(grid, from, to, options, line_of_sight, context);
}

}  // namespace swarmplan
