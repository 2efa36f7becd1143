#pragma once

// The parts of the AEM-BSO path-planning reproduction that test the paper's Table 2 (the
// interpolations against each other) and show its Fig. 4 (convergence), from the runs of
// Tables 2-3.

#include <functional>
#include <string>
#include <vector>

#include "bench/papers/aem_bso_worlds_runs.h"

namespace swarmplan::bench::aem_bso {

// The cell of (planner, interpolation) in an environment.
using CellOf = std::function<const CellStats&(
    const std::string& environment, const std::string& planner, const std::string& interpolation)>;

// "## Table 2: tests": aem-bso with the spline against linear and nearest interpolation
// (Fisher on found, rank-sum on lengths); `summary` gets the discussion's sentence.
std::string InterpolationTestsSection(const std::vector<std::string>& environments,
                                      const CellOf& cell, std::string* summary);

// "## Fig. 4: convergence": the median best z after a few iterations, per planner with the
// spline, and the iteration of the final best of each planner against aem-bso (rank-sum);
// `summary` gets the discussion's sentence.
std::string ConvergenceSection(const std::vector<std::string>& environments,
                               const std::vector<std::string>& planners, int iterations,
                               const CellOf& cell, std::string* summary);

}  // namespace swarmplan::bench::aem_bso
