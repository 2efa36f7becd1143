#pragma once

// The worlds of the binary PSO reproduction (bpso_vertices.cc): 300 x 300 ShapeWorlds whose
// obstacles are rotated rectangles near the start-goal diagonal, so a world with n rectangles
// has D = 4n obstacle vertices (the particle length).

#include <cstdint>
#include <string>

#include "absl/status/statusor.h"
#include "core/map/point.h"
#include "core/map/shape_world.h"

namespace swarmplan::bench {

// Start and goal of every bpso-vertices world. Both are centres of 4 x 4 cells, so the grid
// baseline (rasterised at resolution 4) starts and ends exactly there.
inline Point2 BpsoVerticesStart() { return Point2(10.0, 10.0); }
inline Point2 BpsoVerticesGoal() { return Point2(290.0, 290.0); }

// `rectangles` disjoint rectangles (rotated at random, corners rounded to multiples of 0.5 so
// the shipped JSON is short), at least 8 units apart, clear of start and goal by 25 units, in
// [5, 295]^2; the first, larger (half sides 25-40, the others 8-26), lies across the start-goal
// line so the straight path is blocked. Centres within 70 of that line. Seeded
// and deterministic. INTERNAL when the rejection sampling cannot place them.
absl::StatusOr<ShapeWorld> GenerateBpsoVerticesWorld(int rectangles, uint64_t seed);

}  // namespace swarmplan::bench
