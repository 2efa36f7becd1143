#pragma once

#include "absl/status/status.h"
#include "core/map/occupancy_grid.h"
#include "core/map/point.h"
#include "core/path_metrics.h"

namespace swarmplan::bench {

// Checks a path a grid planner returned: it starts at the centre of `start` and ends at the
// centre of `goal`; every segment runs along one of the 8 grid directions between cell centres,
// and each of its unit steps is a move of the 8-connected grid without corner cutting; the
// metrics call it collision-free; its length is at least the exact optimum (- 1e-9).
// INTERNAL naming the first violation otherwise.
absl::Status CheckGridPath(const OccupancyGrid& grid, const Path& path, const PathMetrics& metrics,
                           Cell start, Cell goal, double optimum);

}  // namespace swarmplan::bench
