#include "core/grid_ops/grid_space.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "absl/status/status.h"
#include "absl/strings/str_format.h"
#include "core/geometry/rasterize.h"
#include "core/graph/grid_search.h"

namespace swarmplan {
namespace {

absl::StatusOr<Cell> EndCell(const OccupancyGrid& grid, const Point3& p, double clearance,
                             const char* what) {
  const Cell c = grid.CellAt(Point2(p.x(), p.y()));
  if (!grid.InBounds(c)) {
    return absl::FailedPreconditionError(absl::StrFormat(
        "%s (%g, %g) lies in cell (%d, %d), outside the planning grid (%d x %d cells of %g)", what,
        p.x(), p.y(), c.x, c.y, grid.width(), grid.height(), grid.resolution()));
  }
  if (!CellUsableWithoutField(grid, c, clearance)) {
    return absl::FailedPreconditionError(absl::StrFormat(
        "%s (%g, %g) lies in cell (%d, %d) of the planning grid (cells of %g), which is blocked "
        "or whose centre is closer than the clearance %g to a blocked cell",
        what, p.x(), p.y(), c.x, c.y, grid.resolution(), clearance));
  }
  return c;
}

struct EndCells {
  Cell start;
  Cell goal;
};

absl::StatusOr<EndCells> FindEndCells(const OccupancyGrid& grid, const Problem& problem) {
  absl::StatusOr<Cell> start = EndCell(grid, problem.start, problem.clearance, "start");
  if (!start.ok()) return start.status();
  absl::StatusOr<Cell> goal = EndCell(grid, problem.goal, problem.clearance, "goal");
  if (!goal.ok()) return goal.status();
  return EndCells{*start, *goal};
}

struct Raster {
  std::shared_ptr<const OccupancyGrid> grid;
  EndCells ends;
};

absl::StatusOr<Raster> RasterAt(const ShapeWorld& world, const Problem& problem,
                                double resolution) {
  absl::StatusOr<OccupancyGrid> raster = RasterizeShapeWorld(world, resolution);
  if (!raster.ok()) return raster.status();
  Raster out;
  out.grid = std::make_shared<const OccupancyGrid>(*std::move(raster));
  absl::StatusOr<EndCells> ends = FindEndCells(*out.grid, problem);
  if (!ends.ok()) return ends.status();
  out.ends = *ends;
  return out;
}

// The rule documented at kAutoRasterCellsPerSide.
absl::StatusOr<Raster> AutoRaster(const ShapeWorld& world, const Problem& problem,
                                  const CollisionChecker& checker) {
  const Bounds2& b = world.bounds();
  const double finest = std::sqrt(b.Width() * b.Height() / kMaxAutoRasterCells);
  double resolution = std::max(b.Width(), b.Height()) / kAutoRasterCellsPerSide;
  const double margin =
      std::min(checker.Clearance(problem.start), checker.Clearance(problem.goal)) -
      problem.clearance;
  if (margin > 0) resolution = std::min(resolution, margin / (1.5 * std::sqrt(2.0)));
  resolution = std::max(resolution, finest);
  while (true) {
    absl::StatusOr<Raster> raster = RasterAt(world, problem, resolution);
    // An endpoint inside an obstacle is unusable at every resolution: no refinement for it.
    if (raster.ok() || !absl::IsFailedPrecondition(raster.status()) || margin <= 0 ||
        resolution <= finest) {
      return raster;
    }
    resolution = std::max(resolution / 2, finest);
  }
}

// Index of the neighbour offset (dx, dy) in [-1, 1]^2; -1 when the cells are not neighbours.
int NeighbourIndex(Cell from, Cell to) {
  const int dx = to.x - from.x, dy = to.y - from.y;
  if (std::abs(dx) > 1 || std::abs(dy) > 1) return -1;
  return (dy + 1) * 3 + (dx + 1);
}

Point3 Flat(const Point3& p) { return Point3(p.x(), p.y(), 0.0); }

}  // namespace

absl::StatusOr<GridSpace> MakeGridSpace(const Problem& problem, double resolution) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("map: no map given");
  GridSpace space;
  space.checker_ = MakeCollisionChecker(*problem.map);
  space.map_ = problem.map;
  if (const OccupancyGrid* grid = problem.map->grid()) {
    // Aliasing constructor: shares the map's ownership, points at its grid.
    space.grid = std::shared_ptr<const OccupancyGrid>(problem.map, grid);
    absl::StatusOr<EndCells> ends = FindEndCells(*space.grid, problem);
    if (!ends.ok()) return ends.status();
    space.start = ends->start;
    space.goal = ends->goal;
  } else if (const ShapeWorld* world = problem.map->world()) {
    absl::StatusOr<Raster> raster = resolution == 0.0 ? AutoRaster(*world, problem, *space.checker_)
                                                      : RasterAt(*world, problem, resolution);
    if (!raster.ok()) return raster.status();
    space.grid = std::move(raster->grid);
    space.start = raster->ends.start;
    space.goal = raster->ends.goal;
  } else {
    return absl::InvalidArgumentError("grid planners need an occupancy grid or a shape world");
  }
  space.clearance_ = problem.clearance;
  space.start_point_ = Flat(problem.start);
  space.goal_point_ = Flat(problem.goal);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int k = (dy + 1) * 3 + (dx + 1);
      const Point2 from_start =
          space.grid->CellCenter(Cell{space.start.x + dx, space.start.y + dy});
      const Point2 to_goal = space.grid->CellCenter(Cell{space.goal.x + dx, space.goal.y + dy});
      space.start_free_[k] = space.checker_->SegmentFree(
          space.start_point_, Point3(from_start.x(), from_start.y(), 0.0), problem.clearance);
      space.goal_free_[k] = space.checker_->SegmentFree(Point3(to_goal.x(), to_goal.y(), 0.0),
                                                        space.goal_point_, problem.clearance);
    }
  }
  space.direct_free_ =
      space.checker_->SegmentFree(space.start_point_, space.goal_point_, problem.clearance);
  return space;
}

Point3 GridSpace::Centre(Cell c) const {
  const Point2 p = grid->CellCenter(c);
  return Point3(p.x(), p.y(), 0.0);
}

bool GridSpace::StartSegmentFree(Cell next) const {
  const int k = NeighbourIndex(start, next);
  return k >= 0 ? start_free_[k] : checker_->SegmentFree(start_point_, Centre(next), clearance_);
}

bool GridSpace::GoalSegmentFree(Cell previous) const {
  const int k = NeighbourIndex(goal, previous);
  return k >= 0 ? goal_free_[k] : checker_->SegmentFree(Centre(previous), goal_point_, clearance_);
}

GridSpace::Ends GridSpace::EndsOf(const std::vector<Cell>& cells) const {
  Ends ends;
  if (cells.size() == 1) {
    ends.replace_start = ends.replace_goal = direct_free_;
    return ends;
  }
  ends.replace_start = StartSegmentFree(cells[1]);
  // With two cells both replaced, the path is the segment from start to goal.
  ends.replace_goal = cells.size() == 2 && ends.replace_start
                          ? direct_free_
                          : GoalSegmentFree(cells[cells.size() - 2]);
  return ends;
}

Path GridSpace::WorldPath(const std::vector<Cell>& cells) const {
  if (cells.empty()) return {};
  const Ends ends = EndsOf(cells);
  Path path;
  path.reserve(cells.size() + 2);
  if (cells.size() == 1 && ends.replace_start) return {start_point_, goal_point_};
  for (const Cell& c : cells) path.push_back(Centre(c));
  if (cells.size() == 1) {
    if (start_point_ != path.front()) path.insert(path.begin(), start_point_);
    if (goal_point_ != path.back()) path.push_back(goal_point_);
    return path;
  }
  if (ends.replace_start) {
    path.front() = start_point_;
  } else if (start_point_ != path.front()) {
    path.insert(path.begin(), start_point_);
  }
  if (ends.replace_goal) {
    path.back() = goal_point_;
  } else if (goal_point_ != path.back()) {
    path.push_back(goal_point_);
  }
  return path;
}

double GridSpace::PathLength(const std::vector<Cell>& cells) const {
  if (cells.empty()) return 0.0;
  const Ends ends = EndsOf(cells);
  const Point3 first = Centre(cells.front()), last = Centre(cells.back());
  if (cells.size() == 1) {
    return ends.replace_start ? (goal_point_ - start_point_).norm()
                              : (first - start_point_).norm() + (goal_point_ - last).norm();
  }
  const Point3 second = Centre(cells[1]);
  double length = CellPathLength(*grid, cells);
  length += ends.replace_start ? (second - start_point_).norm() - (second - first).norm()
                               : (first - start_point_).norm();
  // The point before the goal cell's centre once the start end is attached.
  const Point3 before =
      cells.size() == 2 && ends.replace_start ? start_point_ : Centre(cells[cells.size() - 2]);
  length += ends.replace_goal ? (goal_point_ - before).norm() - (last - before).norm()
                              : (goal_point_ - last).norm();
  return length;
}

bool GridSpace::PathFree(const Path& world_path) const {
  return checker_->PathFree(world_path, clearance_);
}

bool GridSpace::SegmentFree(const Point3& a, const Point3& b) const {
  return checker_->SegmentFree(a, b, clearance_);
}

void SetGridPath(const GridSpace& space, const std::vector<Cell>& cells, double fitness,
                 SearchResult& result) {
  result.fitness = fitness;
  result.path = space.WorldPath(cells);
  result.found = !result.path.empty() && space.PathFree(result.path);
}

std::vector<ParamSpec> GridSpaceParamSpecs(bool with_corner_cutting) {
  std::vector<ParamSpec> specs;
  if (with_corner_cutting) {
    specs.push_back(
        ParamSpec::Bool("allow_corner_cutting", false, "diagonal steps may pass a blocked corner"));
  }
  specs.push_back(
      ParamSpec::Double("resolution", 0.0, 0.0, 1e9, "world units",
                        "cell size when a shape world is rasterised; 0: automatic (the world's "
                        "longer side / 64, finer where the start or goal needs it)")
          .Ours());
  return specs;
}

}  // namespace swarmplan
