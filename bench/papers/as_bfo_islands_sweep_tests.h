#pragma once

// The tests of the AS-BFO sweeps (section 4.1): each parameter's smallest value against its
// largest, with the default and with wandering initial paths, and the paper's claims on the
// parameters held against them.

#include <optional>
#include <string>
#include <vector>

#include "bench/papers/as_bfo_islands_report.h"
#include "bench/papers/as_bfo_islands_significance.h"

namespace swarmplan::bench::as_bfo_islands {

// A sweep's smallest and largest value, with the tests of the largest against the smallest
// (rank-sum on lengths and AIN, Fisher on the optimal runs), for either kind of initial paths.
struct SweepEnds {
  const SweepRow* smallest = nullptr;
  const SweepRow* largest = nullptr;
  MethodTests tests;            // default initial paths
  MethodTests wandering_tests;  // initial paths through up to kWanderingVia cells
};

// One per sweep with at least two values in `rows`.
std::vector<SweepEnds> SweepEndsOf(const std::vector<SweepRow>& rows, double optimum);

std::string SweepTestsSection(const std::vector<SweepEnds>& ends, double optimum);

// The paper's statements on the effect of each parameter, each with what the tests say of it
// (smallest against largest value), as Markdown list items.
std::string SweepClaimVerdicts(const std::vector<SweepEnds>& ends);

// The differences between the smallest and largest values that the tests support, e.g.
// "P = 80 against P = 10: lengths lower (p = 0.002)"; empty when there are none.
std::string SweepDifferences(const std::vector<SweepEnds>& ends, bool wandering);

// The paper's best single values of environment 2 (the sweep world's), as Markdown list items:
// each against every other value of its sweep by the rank-sum test (lengths for "shortest at",
// AIN for "fewest at"), with the wandering initial paths, and our own lowest value beside it.
// Empty when no sweep has the named value and another.
std::string PaperBestValueVerdicts(const std::vector<SweepRow>& rows);

}  // namespace swarmplan::bench::as_bfo_islands
