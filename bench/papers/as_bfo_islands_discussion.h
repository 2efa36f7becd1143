#pragma once

// The discussion of the AS-BFO islands report, computed from its runs, its tests and the
// paper's Table 4: every figure it states comes from them.

#include <string>
#include <vector>

#include "bench/papers/as_bfo_islands_morris.h"
#include "bench/papers/as_bfo_islands_report.h"
#include "bench/papers/as_bfo_islands_sweep_tests.h"

namespace swarmplan::bench::as_bfo_islands {

struct DiscussionInputs {
  const std::vector<std::vector<World>>& worlds;
  const Table4& outcomes;
  const World& sweep_world;
  const std::vector<SweepRow>& sweep_rows;
  const std::vector<SweepEnds>& sweep_ends;
  const std::vector<MorrisAnalysis>& morris;
  int replicated_worlds = 0;
  int replicated_runs = 0;
  std::string replicated_differences;  // from ReplicatedIslandsSection
  bool quick = false;
};

std::string Discussion(const DiscussionInputs& in);

}  // namespace swarmplan::bench::as_bfo_islands
