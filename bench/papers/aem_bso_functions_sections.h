#pragma once

// The tables of the AEM-BSO Table 1 report, each from the cells of its runs.

#include <string>
#include <vector>

#include "bench/papers/aem_bso_functions_paper.h"
#include "bench/papers/aem_bso_functions_runs.h"
#include "bench/papers/aem_bso_test_functions.h"

namespace swarmplan::bench::aem_bso {

// "1.23e-05"; "–" when there is no value.
std::string Sci(std::optional<double> value);

// cells[f][c]: function f (of `functions`), configuration c (of `labels`).
using CellGrid = std::vector<std::vector<FunctionCell>>;

// Best, mean and std of every cell; the paper's best and mean in parentheses when `paper` is
// given (its columns in kAlgorithms' order, which `labels` must follow).
std::string ResultsTable(const std::vector<const TestFunction*>& functions,
                         const std::vector<std::string>& labels, const CellGrid& cells,
                         const std::array<PaperRow, 10>* paper);

// Whether `a`'s values are significantly below `b`'s: rank-sum p < kSignificanceLevel and a
// lower median.
bool SignificantlyLower(const std::vector<double>& a, const std::vector<double>& b);

// Column 0 against every other column, per function: the rank-sum test on the final values.
// `lower_than_all` receives the functions where column 0 is significantly lower than every
// other column; `lower_than_baselines` those where it is lower than columns 2.. (BSO, PSO, BA:
// the baselines, without the paper's own variant in column 1).
std::string SignificanceTable(const std::vector<const TestFunction*>& functions,
                              const std::vector<std::string>& labels, const CellGrid& cells,
                              std::vector<std::string>* lower_than_all,
                              std::vector<std::string>* lower_than_baselines);

// The mean of every cell, and column 0 against each column named in `tested` by rank-sum.
std::string MeansTable(const std::vector<const TestFunction*>& functions,
                       const std::vector<std::string>& labels, const CellGrid& cells,
                       const std::vector<int>& tested);

// The test functions, their ranges and minima and how we read them.
std::string FunctionsTable();

// "- `aem-bso`: inertia = cosine, ..., k3 = -1 (ours)": the optimiser's defaults.
std::string ParameterLine(const std::string& planner_id);

}  // namespace swarmplan::bench::aem_bso
