#pragma once

// The canyon worlds of the bas-canyon reproduction: the shipped canyon (world 0) and the ones the
// same generator draws for the world replication, each with its start, goal and the
// terrain-lattice yardstick of the paper's fitness.

#include <cstdint>
#include <string>

#include "absl/status/statusor.h"
#include "core/algorithms/exact/terrain_lattice.h"
#include "core/map/map.h"

namespace swarmplan::bench::bas {

inline constexpr uint64_t kCanyonSeed = 2020;
inline constexpr char kCanyonFile[] = "canyon.asc";
inline constexpr double kStartHeightAboveGround = 1.0;
// The lattice's height step: finer in full runs; quick runs only check that rows are produced.
inline constexpr double kLatticeVerticalStep = 0.25;
inline constexpr double kQuickLatticeVerticalStep = 1.0;

struct CanyonWorld {
  int index = 0;  // 0: the shipped canyon
  uint64_t seed = kCanyonSeed;
  MapPtr map;
  Point3 start, goal;
  TerrainLatticeResult lattice;  // the yardstick, from start to goal, clearance 0
};

// The .asc text of the canyon drawn from `seed` (what `generate` writes for kCanyonSeed).
std::string CanyonAscText(uint64_t seed);

// The canyon of world `index` of the replication (seed ReplicatedWorldSeed(kCanyonSeed, index)),
// drawn in memory; world 0 is the shipped one. `start_y`: the start's row coordinate on the first
// column (the mouth by default, see CanyonShape); the goal is the mouth on the last column.
absl::StatusOr<CanyonWorld> DrawCanyonWorld(int index, double lattice_vertical_step);

// The shipped canyon under `worlds_dir`/bas-canyon/, from start row `start_y`.
absl::StatusOr<CanyonWorld> LoadShippedCanyon(const std::string& worlds_dir, double start_y,
                                              double lattice_vertical_step);

// Whether a path's middle waypoint lies in the deep right branch (y above the mouth).
bool InRightBranch(const Path& path);

}  // namespace swarmplan::bench::bas
