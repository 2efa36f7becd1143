#include "core/grid_ops/grid_space.h"

#include "absl/status/status.h"
#include "absl/strings/str_format.h"
#include "core/geometry/collision.h"
#include "core/geometry/rasterize.h"
#include "core/graph/grid_search.h"

namespace swarmplan {
namespace {

absl::StatusOr<Cell> EndCell(const OccupancyGrid& grid, const Point3& p, double clearance,
                             const char* what) {
  const Cell c = grid.CellAt(Point2(p.x(), p.y()));
  if (!grid.InBounds(c)) {
    return absl::FailedPreconditionError(
        absl::StrFormat("%s (%g, %g) is outside the planning grid", what, p.x(), p.y()));
  }
  if (!CellUsable(grid, c, clearance)) {
    return absl::FailedPreconditionError(absl::StrFormat(
        "%s (%g, %g) lies in grid cell (%d, %d), which is blocked or closer than the clearance "
        "%g to a blocked cell",
        what, p.x(), p.y(), c.x, c.y, clearance));
  }
  return c;
}

}  // namespace

absl::StatusOr<GridSpace> MakeGridSpace(const Problem& problem, double resolution) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("map: no map given");
  GridSpace space;
  if (const OccupancyGrid* grid = problem.map->grid()) {
    // Aliasing constructor: shares the map's ownership, points at its grid.
    space.grid = std::shared_ptr<const OccupancyGrid>(problem.map, grid);
  } else if (const ShapeWorld* world = problem.map->world()) {
    absl::StatusOr<OccupancyGrid> raster = RasterizeShapeWorld(*world, resolution);
    if (!raster.ok()) return raster.status();
    space.grid = std::make_shared<const OccupancyGrid>(*std::move(raster));
  } else {
    return absl::InvalidArgumentError("grid planners need an occupancy grid or a shape world");
  }
  absl::StatusOr<Cell> start = EndCell(*space.grid, problem.start, problem.clearance, "start");
  if (!start.ok()) return start.status();
  absl::StatusOr<Cell> goal = EndCell(*space.grid, problem.goal, problem.clearance, "goal");
  if (!goal.ok()) return goal.status();
  space.start = *start;
  space.goal = *goal;
  return space;
}

void SetGridPath(const Problem& problem, const OccupancyGrid& grid, const std::vector<Cell>& cells,
                 double fitness, SearchResult& result) {
  result.fitness = fitness;
  if (cells.empty()) {
    result.path.clear();
    result.found = false;
    return;
  }
  result.path = CellPathToWorld(grid, cells);
  result.found = MakeCollisionChecker(*problem.map)->PathFree(result.path, problem.clearance);
}

std::vector<ParamSpec> GridSpaceParamSpecs(bool with_corner_cutting) {
  std::vector<ParamSpec> specs;
  if (with_corner_cutting) {
    specs.push_back(
        ParamSpec::Bool("allow_corner_cutting", false, "diagonal steps may pass a blocked corner"));
  }
  specs.push_back(ParamSpec::Double("resolution", 1.0, 1e-6, 1e9, "world units",
                                    "cell size when a shape world is rasterised")
                      .Ours());
  return specs;
}

}  // namespace swarmplan
