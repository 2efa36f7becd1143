#pragma once

#include <cstdint>
#include <string>

#include "absl/time/time.h"
#include "core/fitness/fleet_objective.h"
#include "core/map/map.h"

namespace swarmplan {

// The most paths a plan may ask for (Problem::alternatives).
inline constexpr int kMaxAlternatives = 8;
// The most via-points a plan may pass through.
inline constexpr int kMaxViaPoints = 32;

struct Limits {
  int max_iterations = 0;  // 0: the planner's own default
  absl::Duration time_budget = absl::InfiniteDuration();
};

// What to plan: immutable, owned by the caller, shared read-only with the planner.
// Coordinates are world coordinates on every map kind: on 2D maps z is ignored, on a terrain
// x and y are in the unit of its cell size and z is a height (see Terrain). `clearance` is the
// distance every point of the path keeps from obstacles.
struct Problem {
  MapPtr map;
  Point3 start = Point3::Zero();
  Point3 goal = Point3::Zero();
  double clearance = 0.0;
  // What the fleet asks of the path beyond the hard clearance (preferred clearance, turning
  // radius, their weights): the objective of the seeded planners.
  FleetObjective fleet;
  // Up to this many paths in distinct corridors, the result's included: a planner that can
  // (the seeded waypoint swarms) returns the others as SearchResult::alternatives. 0 or 1:
  // none.
  int alternatives = 0;
  Limits limits;
  uint64_t seed = 1;  // never 0 here: RunPlan resolves "pick one" before calling a planner
};

}  // namespace swarmplan
