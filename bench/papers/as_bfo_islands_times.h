#pragma once

// The run times of the AS-BFO islands reproduction, in one section of their own: Table 4's mean
// times, their rank-sum tests against AS-BFO, the sweeps' times and the ratios between planners.
// Wall times differ from run to run, so the report's digest skips this section (kTimesHeading).

#include <string>
#include <vector>

#include "bench/papers/as_bfo_islands_report.h"

namespace swarmplan::bench::as_bfo_islands {

inline constexpr char kTimesHeading[] = "## Run times";

std::string RunTimesSection(const std::vector<std::vector<World>>& worlds, const Table4& outcomes,
                            const std::vector<SweepRow>& sweep_rows);

}  // namespace swarmplan::bench::as_bfo_islands
