#pragma once

// The AEM-BSO paper's Fig. 2 (the optimisers' iteration curves on the ten test functions), from
// the best-so-far values the Table 1 runs keep at a few checkpoints.

#include <string>
#include <vector>

#include "bench/papers/aem_bso_functions_sections.h"

namespace swarmplan::bench::aem_bso {

// "## Fig. 2: convergence on the test functions (D = dim)": per function and optimiser the
// median best so far at each checkpoint of `iterations`, and where column 0 (AEM-BSO) is
// significantly below or above it (rank-sum per checkpoint). The columns from `first_baseline`
// on are the baselines (BSO, PSO, BA; the others are the paper's own variants). `summary` gets
// one sentence for the discussion.
std::string ConvergenceSection(const std::vector<const TestFunction*>& functions,
                               const std::vector<std::string>& labels, const CellGrid& cells,
                               size_t first_baseline, int dim, int iterations,
                               std::string* summary);

}  // namespace swarmplan::bench::aem_bso
