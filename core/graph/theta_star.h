#pragma once

#include "core/geometry/collision.h"
#include "core/graph/grid_search.h"
#include "core/map/occupancy_grid.h"

namespace swarmplan {

// Theta* on a grid: any-angle paths between cell centres. Moves follow `options` as in
// SearchGrid (usable cells, connectivity, corner cutting, clearance); a shortcut from a node's
// parent to a neighbour is taken when `checker.SegmentFree(centre, centre, options.clearance)`.
// `checker` must be the checker of `grid`'s map. The result's `cells` are the turning cells,
// start and goal included; `length` is the Euclidean length of the polyline through their
// centres.
GridSearchResult ThetaStar(const OccupancyGrid& grid, const CollisionChecker& checker, Cell from,
                           Cell to, const GridSearchOptions& options = {},
                           GridSearchContext* context = nullptr);

}  // namespace swarmplan
