#pragma once

// Running the AS-BFO islands reproduction's planners: a world with A*'s optimum, and the checked
// runs of one planner configuration on it.

#include <cstdint>
#include <string>

#include "absl/status/statusor.h"
#include "bench/papers/as_bfo_islands_report.h"
#include "bench/papers/plan_once.h"
#include "core/map/occupancy_grid.h"

namespace swarmplan::bench::as_bfo_islands {

// The world of `grid` (an n x n island grid of `environment`), with A*'s optimum between the
// corners; FAILED_PRECONDITION when A* finds no path, INTERNAL when its path fails the check.
absl::StatusOr<World> MakeWorld(const std::string& environment, OccupancyGrid grid, uint64_t seed);

// `runs` runs of `spec` on `world` (seeds seed ... seed + runs - 1), every found path checked.
absl::StatusOr<Outcome> RunConfig(const PlanSpec& spec, const World& world, int runs,
                                  uint64_t seed);

// The runs of `outcome` whose path is A*'s optimum (up to 1e-9), out of all runs.
int OptimalRuns(const Outcome& outcome, double optimum);

}  // namespace swarmplan::bench::as_bfo_islands
