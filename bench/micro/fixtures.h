#pragma once

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/statusor.h"
#include "core/geometry/collision.h"
#include "core/map/map.h"

namespace swarmplan::bench {

// A benchmark cannot run without its fixture: the value, or a message and abort.
template <typename T>
T ValueOrDie(absl::StatusOr<T> value) {
  if (!value.ok()) {
    std::cerr << "micro-benchmark fixture: " << value.status() << "\n";
    std::abort();
  }
  return *std::move(value);
}

// The shared Moving AI maps' folder: $SWARMPLAN_MOVINGAI_DIR, default
// ../shared/benchmarks/movingai (the benchmarks run from the repository's root).
std::string MovingAiDir();

// Maps shared by the micro-benchmarks (core/map/generate.h, seed 1), built once per process.

// A size × size grid (resolution 1) with 20% of its cells blocked, scattered.
const Map& RandomGridMap(int size);

// A 100 × 100 world, 20% covered by circles and convex polygons (RandomWorldOptions defaults).
const Map& RandomShapeWorldMap();

// `count` segments between random points of the map that are free of obstacles (clearance 0),
// seeded; points are drawn in [lo, hi]² (world coordinates).
std::vector<std::pair<Point3, Point3>> RandomSegments(const CollisionChecker& checker, double lo,
                                                      double hi, int count, uint64_t seed);

// `count` pairs of free cells of the grid, seeded.
std::vector<std::pair<Cell, Cell>> RandomFreeCellPairs(const OccupancyGrid& grid, int count,
                                                       uint64_t seed);

}  // namespace swarmplan::bench
