#pragma once

// The discussion of the aem-bso-worlds report, computed from its runs and the paper's numbers.

#include <string>
#include <vector>

#include "bench/papers/aem_bso_worlds_world_run.h"

namespace swarmplan::bench::aem_bso {

// The sentences the report's sections wrote for the discussion.
struct DiscussionTexts {
  std::string significant;     // SignificanceSection
  std::string replicated;      // the ten-world Table 3
  std::string unstated;        // UnstatedSettingsSection
  std::string equal_budget;    // EqualBudgetSection
  std::string interpolations;  // InterpolationTestsSection
  std::string convergence;     // ConvergenceSection
  std::string waypoints;       // WaypointCountSentence
};

std::string Discussion(const std::vector<WorldRun>& worlds, int iterations,
                       const DiscussionTexts& texts);

}  // namespace swarmplan::bench::aem_bso
