#pragma once

// The discussion of the bpso-vertices report, computed from its runs and the paper's numbers:
// every figure it quotes comes from the runs or the paper, and every difference it names comes
// with a test at p < kSignificanceLevel.

#include <string>

#include "bench/papers/bpso_vertices_figures.h"

namespace swarmplan::bench::bpso {

// `assistant_item`: AssistantSection's summary; `replicated_summary`: the items of
// ReplicatedBpsoSummary.
std::string Discussion(const FigureRuns& figures, const std::string& assistant_item,
                       const std::string& replicated_summary);

// The range of the paper's times over ours in Table 1 as the discussion quotes it, "A to B
// times", each end formatted as its table cell.
std::string PaperOverOurTimeRange(const FigureRuns& figures);

}  // namespace swarmplan::bench::bpso
