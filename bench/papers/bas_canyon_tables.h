#pragma once

// The bas-canyon report's tables of fitness and of time per run.

#include <string>

#include "bench/papers/bas_canyon_runs.h"

namespace swarmplan::bench::bas {

// Per row: found, improved on the first path, best, median [95 % CI], mean, std, median over
// `yardstick` (the lattice optimum), deep branch, mean iteration of the best, and the paper's
// best / mean / std where it gives them.
std::string FitnessTable(const RowSet& set, double yardstick);

// Per row: our mean time per run and the paper's (rows the paper times only). For a "## Time"
// section, which the report's digest skips.
std::string TimeTable(const RowSet& set);

// "The paper's aco took 5.2x as long as its bas; ours 81x." from the mean times.
std::string TimeRatioSentence(const RowSet& set, const std::string& slow, const std::string& fast);

}  // namespace swarmplan::bench::bas
