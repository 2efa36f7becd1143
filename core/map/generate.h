#pragma once

// Seeded random maps for benchmarks: grids and ShapeWorlds with a target obstacle ratio. The
// same options and seed give the same map on every platform (swarmplan::Rng draws only).

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/occupancy_grid.h"
#include "core/map/shape_world.h"

namespace swarmplan {

struct RandomGridOptions {
  int width = 64;
  int height = 64;
  // Share of all cells that are blocked, in [0, 0.95]: exactly round(ratio * width * height).
  double obstacle_ratio = 0.2;
  // Obstacles are squares of block_size x block_size cells (1: scattered single cells). The
  // last square is filled only up to the exact blocked count.
  int block_size = 1;
  // Cells that stay free (e.g. start and goal).
  std::vector<Cell> keep_free;
  double resolution = 1.0;
};

absl::StatusOr<OccupancyGrid> RandomGrid(const RandomGridOptions& options, uint64_t seed);
// Scattered single blocked cells.
absl::StatusOr<OccupancyGrid> RandomGrid(int width, int height, double obstacle_ratio,
                                         uint64_t seed);

struct RandomWorldOptions {
  Bounds2 bounds{Point2(0, 0), Point2(100, 100)};
  // Target share of the bounds covered by the union of the obstacles, in [0, 0.9]. Obstacles
  // are added until the share (measured by CoveredShare) reaches it, so it may overshoot by at
  // most the area of one obstacle.
  double obstacle_ratio = 0.2;
  // Circle radius, or the circumradius of a polygon, uniform in [min_radius, max_radius].
  double min_radius = 2.0;
  double max_radius = 6.0;
  // Probability that an obstacle is a convex polygon rather than a circle.
  double polygon_share = 0.5;
  int min_vertices = 3;
  int max_vertices = 8;
  // No obstacle comes within keep_clear_radius of these points (start, goal, ...).
  std::vector<Point2> keep_clear;
  double keep_clear_radius = 0.0;
};

absl::StatusOr<ShapeWorld> RandomShapeWorld(const RandomWorldOptions& options, uint64_t seed);

// Exactly `circles` circles with radii uniform in [min_radius, max_radius] and centres uniform
// in the bounds, none covering a keep-clear point (nor within keep_clear_radius of one).
absl::StatusOr<ShapeWorld> RandomShapeWorld(const Bounds2& bounds, int circles, double min_radius,
                                            double max_radius, uint64_t seed,
                                            const std::vector<Point2>& keep_clear = {},
                                            double keep_clear_radius = 0.0);

// Share of the bounds covered by obstacles, measured at the centres of a samples x samples
// lattice over the bounds.
double CoveredShare(const ShapeWorld& world, int samples = 256);

}  // namespace swarmplan
