#include "bench/papers/bas_canyon_world.h"

#include <memory>
#include <utility>

#include "absl/strings/str_cat.h"
#include "bench/papers/bas_canyon_terrain.h"
#include "bench/papers/world_replication.h"
#include "core/map/io/map_io.h"
#include "core/path_metrics.h"

namespace swarmplan::bench::bas {
namespace {

absl::StatusOr<CanyonWorld> WorldOnMap(Map loaded, double start_y, double lattice_vertical_step) {
  CanyonWorld world;
  world.map = std::make_shared<const Map>(std::move(loaded));
  const Terrain& terrain = *world.map->terrain();
  const CanyonShape shape;
  const Point2 start_xy = terrain.ToWorld(Point2(0, start_y));
  const Point2 goal_xy = terrain.ToWorld(Point2(terrain.width() - 1, shape.mouth_y));
  world.start =
      Point3(start_xy.x(), start_xy.y(), terrain.GroundAt(start_xy) + kStartHeightAboveGround);
  world.goal =
      Point3(goal_xy.x(), goal_xy.y(), terrain.GroundAt(goal_xy) + kStartHeightAboveGround);
  TerrainLatticeOptions options;
  options.vertical_step = lattice_vertical_step;
  absl::StatusOr<TerrainLatticeResult> lattice =
      TerrainLatticeOptimum(terrain, world.start, world.goal, 0.0, options);
  if (!lattice.ok()) return lattice.status();
  if (lattice->path.empty()) return absl::InternalError("bas-canyon: no lattice yardstick path");
  if (!EvaluatePath(*world.map, lattice->path, 0.0).collision_free) {
    return absl::InternalError("bas-canyon: the lattice yardstick path is not collision-free");
  }
  world.lattice = std::move(*lattice);
  return world;
}

}  // namespace

std::string CanyonAscText(uint64_t seed) {
  const CanyonShape shape;
  return HeightsToAsc(shape.width, shape.depth, CanyonHeights(shape, seed));
}

absl::StatusOr<CanyonWorld> DrawCanyonWorld(int index, double lattice_vertical_step) {
  const uint64_t seed = ReplicatedWorldSeed(kCanyonSeed, index);
  absl::StatusOr<Map> map = ParseMap("terrain-asc", {{kCanyonFile, CanyonAscText(seed)}});
  if (!map.ok()) return map.status();
  absl::StatusOr<CanyonWorld> world =
      WorldOnMap(std::move(*map), CanyonShape().mouth_y, lattice_vertical_step);
  if (!world.ok()) return world.status();
  world->index = index;
  world->seed = seed;
  return world;
}

absl::StatusOr<CanyonWorld> LoadShippedCanyon(const std::string& worlds_dir, double start_y,
                                              double lattice_vertical_step) {
  absl::StatusOr<Map> map =
      LoadMapFile(absl::StrCat(worlds_dir, "/bas-canyon/", kCanyonFile), "terrain-asc");
  if (!map.ok()) return map.status();
  return WorldOnMap(std::move(*map), start_y, lattice_vertical_step);
}

bool InRightBranch(const Path& path) {
  return !path.empty() && path[path.size() / 2].y() > CanyonShape().mouth_y;
}

}  // namespace swarmplan::bench::bas
