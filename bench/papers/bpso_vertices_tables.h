#pragma once

// The Markdown tables of the bpso-vertices report, from its runs and their tests.

#include <string>

#include "bench/papers/bpso_vertices_figures.h"

namespace swarmplan::bench::bpso {

// The shipped worlds: optimum and the best path the encoding can express.
std::string WorldsTable(const FigureRuns& figures);

// Table 1 as the paper's, with our means, times and the paper's time over ours.
inline constexpr char kPaperOverOurTimeHeader[] = "paper time / ours";
std::string SwarmSizeTable(const FigureRuns& figures);
// N = 2D against N = 1D per world: medians, rank-sum tests on length and time, time ratios.
std::string SwarmSizeTestTable(const FigureRuns& figures);

// Fig. 4: mean length (success) per mutation probability and world.
std::string MutationTable(const FigureRuns& figures);
// Per world: the best probability (lowest median) against the paper's 0.1 and the others.
std::string MutationTestTable(const FigureRuns& figures);

// Fig. 5: mean best fitness at checkpoints per variant, one table per world.
std::string ConvergenceTables(const FigureRuns& figures);
// Per world: every variant's final length, iteration of the final best and success, tested
// against the paper's variant.
std::string ConvergenceTestTable(const FigureRuns& figures);

}  // namespace swarmplan::bench::bpso
