#pragma once

// The BAS paper's 2D experiments (its Figs. 10-11): BAS against PSO and against APF on a plane
// with circular obstacles, two path points joined by a cubic spline. The paper's world is not
// published; we use the generated 10-circle world of the aem-bso-worlds reproduction (100 x 100,
// start (10, 10), goal (90, 90)), which is the same kind of map.

#include <string>

#include "absl/status/statusor.h"
#include "bench/papers/experiment.h"

namespace swarmplan::bench::bas {

// The section "## Figs. 10-11: 2D" with its tables, tests and findings: `runs` runs per planner
// (seeds options.seed + i) over options.jobs threads, `iterations` iterations each.
absl::StatusOr<std::string> TwoDSection(const ExperimentOptions& options, int runs, int iterations);

}  // namespace swarmplan::bench::bas
