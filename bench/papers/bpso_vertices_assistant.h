#pragma once

// Fig. 5's explanation, instrumented: how many of the double structure's assistant positions
// saturate the sigmoid (so their bits stop changing), with and without mutation, and what a
// bound on them changes. Runs the planner directly to read its trace.

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/bpso_vertices_figures.h"

namespace swarmplan::bench::bpso {

// The bound of the bounded variants: sigmoid(4) = 0.982, so a bit keeps a 1.8 % chance to flip.
inline constexpr double kAssistantBound = 4.0;

struct AssistantVariant {
  std::string label;
  double mutation = 0.0;
  double bound = 0.0;  // 0: unbounded (the paper's)
};
// With mutation unbounded (the paper's), bounded; without mutation unbounded, bounded.
const std::vector<AssistantVariant>& AssistantVariants();

struct AssistantRuns {
  Runs runs;
  std::vector<std::vector<double>> saturated;  // [run][iteration]: share of saturated positions
  std::vector<double> final_magnitude;         // [run]: mean |position| after the last iteration
};

struct AssistantWorld {
  size_t world = 0;                     // index into FigureRuns::worlds
  std::vector<AssistantRuns> variants;  // as AssistantVariants()
};

// The variants on the worlds of kConvergenceVertices, N = 1.5 D, `runs` runs of `iterations`;
// every found path checked (collision-free, from start to goal, no shorter than the optimum).
absl::StatusOr<std::vector<AssistantWorld>> RunAssistantWorlds(const FigureRuns& figures,
                                                               uint64_t first_seed, int runs,
                                                               int iterations, std::ostream* log);

// The report's section; `summary` gets the discussion's item.
std::string AssistantSection(const FigureRuns& figures, const std::vector<AssistantWorld>& worlds,
                             std::string* summary);

}  // namespace swarmplan::bench::bpso
