#pragma once

#include <vector>

#include "absl/status/statusor.h"
#include "core/map/point.h"
#include "core/problem.h"
#include "core/stop_token.h"

namespace swarmplan {

// The most seed paths FindSeedPaths returns.
inline constexpr int kMaxSeedPaths = 8;

// A collision-free path from the problem's start to its goal, exactly, keeping its clearance.
struct SeedPath {
  Path path;
  double length = 0.0;  // PathLength, world units
};

// Up to `count` seed paths in distinct corridors (homotopy classes), shortest first: the exact
// optimum of the map's kind (exact-any-angle on grids, visibility-graph on shape worlds), then,
// each in turn, the exact optimum once the corridors of the paths before it are cut: a wall
// across each earlier path at the middle of its length (or a third from either end when the
// middle's wall would block the start or goal), along the path's normal from obstacle to
// obstacle, so no later path can take that corridor. Fewer than `count` when the map has no
// further corridor. On terrain the lattice optimum alone (terrain-lattice). Empty when no path
// exists. The exact planners' errors (an endpoint they cannot use) are returned as they are;
// `stop` is passed to every search, and a tripped stop ends the list early.
// With a preferred clearance above the hard one (problem.fleet), the seeds are first sought
// keeping the preferred clearance, then halfway between the two, then a quarter of the way, then
// the hard clearance: the first that gives a path gives every seed, so a fleet's seeds leave
// room where the map does (and gaps exactly as wide as the hard clearance allows, where no
// curve fits, only where the map has no other way).
// On grids the start and goal need keep only the hard clearance (exact-any-angle's margin).
absl::StatusOr<std::vector<SeedPath>> FindSeedPaths(const Problem& problem, int count,
                                                    const StopToken& stop);

}  // namespace swarmplan
