#include "core/seeds/seed_paths.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <utility>

#include "absl/strings/str_cat.h"
#include "core/algorithms/exact/exact_any_angle.h"
#include "core/algorithms/exact/exact_planners.h"
#include "core/algorithms/exact/terrain_lattice_planner.h"
#include "core/geometry/collision.h"
#include "core/path_metrics.h"
#include "core/seeds/corridor.h"

namespace swarmplan {
namespace {

struct Wall {
  Point2 a, b;
};

PlannerInfo ExactInfoFor(MapKind kind) {
  switch (kind) {
    case MapKind::kOccupancyGrid:
      return ExactAnyAngleInfo();
    case MapKind::kShapeWorld:
      return VisibilityGraphInfo();
    case MapKind::kTerrain:
      break;
  }
  return TerrainLatticeInfo();
}

double Diagonal(const Map& map) {
  if (const OccupancyGrid* grid = map.grid()) {
    return std::hypot(grid->width(), grid->height()) * grid->resolution();
  }
  const Bounds2& b = map.world()->bounds();
  return std::hypot(b.Width(), b.Height());
}

// How far a wall reaches past the free extent, into the obstacle it meets.
double WallOverlap(const Map& map, double clearance) {
  if (const OccupancyGrid* grid = map.grid()) return clearance + 1.5 * grid->resolution();
  return clearance + 1e-3 * Diagonal(map);
}

// Adds the free cells along the wall that `blocked` does not hold yet.
void AddWallCells(const OccupancyGrid& grid, const Wall& wall, std::vector<Cell>& blocked) {
  const double step = 0.25 * grid.resolution();
  const int n = 1 + static_cast<int>(std::ceil((wall.b - wall.a).norm() / step));
  for (int i = 0; i <= n; ++i) {
    const Cell c = grid.CellAt(wall.a + (wall.b - wall.a) * (static_cast<double>(i) / n));
    if (!grid.InBounds(c) || grid.IsBlocked(c.x, c.y)) continue;
    if (std::find(blocked.begin(), blocked.end(), c) != blocked.end()) continue;
    blocked.push_back(c);
  }
}

// `original` with every wall added as an obstacle; on grids a patch of `original`, so that the
// exact planner's clearance grids and the distance field are measured again only along the walls.
absl::StatusOr<MapPtr> WithWalls(const MapPtr& original, const std::vector<Wall>& walls) {
  if (const OccupancyGrid* grid = original->grid()) {
    std::vector<Cell> blocked;
    for (const Wall& wall : walls) AddWallCells(*grid, wall, blocked);
    OccupancyGrid cut = grid->WithBlocked(blocked);
    return std::make_shared<const Map>(Map::Data(std::move(cut)),
                                       Map::GridPatch{original, std::move(blocked)});
  }
  const ShapeWorld& world = *original->world();
  const double half_thickness = 1e-4 * Diagonal(*original);
  std::vector<Polygon> polygons = world.polygons();
  for (const Wall& wall : walls) {
    const Point2 along = (wall.b - wall.a).normalized();
    const Point2 side(-along.y() * half_thickness, along.x() * half_thickness);
    Polygon slab;
    const Point2 corners[] = {wall.a - side, wall.b - side, wall.b + side, wall.a + side};
    slab.vertices.assign(std::begin(corners), std::end(corners));
    polygons.push_back(std::move(slab));
  }
  // A wall may reach past the bounds: the map's edge is no gap.
  absl::StatusOr<ShapeWorld> cut =
      ShapeWorld::Create(world.bounds(), world.circles(), std::move(polygons));
  if (!cut.ok()) return cut.status();
  return std::make_shared<const Map>(Map::Data(*std::move(cut)));
}

// The wall across `path` at `fraction` of its length, from obstacle to obstacle.
Wall WallAcross(const CollisionChecker& checker, const Map& map, const Path& path, double fraction,
                double clearance) {
  const PathPosition at = PositionAt(path, fraction * PathLength(path));
  const Point2 normal = SegmentNormal(path, at.segment);
  const double cap = Diagonal(map);
  const double tolerance = 1e-3 * cap;
  const double overlap = WallOverlap(map, clearance);
  const double left = FreeExtent(checker, at.point, normal, clearance, cap, tolerance) + overlap;
  const double right = FreeExtent(checker, at.point, -normal, clearance, cap, tolerance) + overlap;
  return {at.point - right * normal, at.point + left * normal};
}

// The seeds for `problem` with its clearance set to the one they keep.
absl::StatusOr<std::vector<SeedPath>> SeedPathsKeeping(const Problem& problem, Planner& planner,
                                                       int count, const StopToken& stop) {
  std::vector<SeedPath> seeds;
  std::vector<Wall> walls;
  Problem cut = problem;
  cut.limits = Limits();
  NullObserver observer;
  while (static_cast<int>(seeds.size()) < count) {
    if (stop.Check(0) != StopReason::kNone) break;
    absl::StatusOr<SearchResult> found = planner.Solve(cut, stop, observer);
    if (!found.ok()) {
      if (seeds.empty()) return found.status();
      break;
    }
    if (!found->found || found->path.size() < 2) break;
    seeds.push_back({found->path, PathLength(found->path)});
    if (static_cast<int>(seeds.size()) == count) break;

    // Cut the new seed's corridor; the walls stay where the endpoints keep their clearance.
    const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*cut.map);
    bool walled = false;
    for (const double fraction : {0.5, 1.0 / 3.0, 2.0 / 3.0}) {
      std::vector<Wall> more = walls;
      more.push_back(WallAcross(*checker, *cut.map, found->path, fraction, problem.clearance));
      absl::StatusOr<MapPtr> map = WithWalls(problem.map, more);
      if (!map.ok()) return map.status();
      const std::unique_ptr<const CollisionChecker> cut_checker = MakeCollisionChecker(**map);
      if (!cut_checker->PointFree(problem.start, problem.clearance) ||
          !cut_checker->PointFree(problem.goal, problem.clearance)) {
        continue;
      }
      walls = std::move(more);
      cut.map = *std::move(map);
      walled = true;
      break;
    }
    if (!walled) break;
  }
  return seeds;
}

}  // namespace

absl::StatusOr<std::vector<SeedPath>> FindSeedPaths(const Problem& problem, int count,
                                                    const StopToken& stop) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("problem has no map");
  if (count < 1 || count > kMaxSeedPaths) {
    return absl::InvalidArgumentError(
        absl::StrCat("seed path count must be in [1, ", kMaxSeedPaths, "], got ", count));
  }
  const PlannerInfo info = ExactInfoFor(problem.map->kind());
  if (problem.map->is_3d()) count = 1;

  // Rungs from the most room to none: on grids the exact planner's margin over the hard
  // clearance (the ends need only keep the hard clearance); elsewhere a larger clearance.
  const double hard = problem.clearance;
  const double room = problem.fleet.preferred_clearance - hard;
  std::vector<double> rungs = {0.0};
  if (!problem.map->is_3d() && room > 0) rungs = {room, 0.5 * room, 0.25 * room, 0.0};
  const bool grid = problem.map->grid() != nullptr;
  for (const double extra : rungs) {
    ParamValues given;
    if (grid) given["margin"] = extra;
    absl::StatusOr<ParamSet> params = ParamSet::Resolve(info.params, given);
    if (!params.ok()) return params.status();
    const std::unique_ptr<Planner> planner = info.factory(*params);
    Problem keeping = problem;
    if (!grid) keeping.clearance = hard + extra;
    absl::StatusOr<std::vector<SeedPath>> seeds = SeedPathsKeeping(keeping, *planner, count, stop);
    if (extra == 0.0 || (seeds.ok() && !seeds->empty())) return seeds;
    if (stop.Check(0) != StopReason::kNone) return std::vector<SeedPath>();
  }
  return std::vector<SeedPath>();
}

}  // namespace swarmplan
