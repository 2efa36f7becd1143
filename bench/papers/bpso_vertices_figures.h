#pragma once

// The runs behind the bpso-vertices report's reproductions of Table 1 (swarm size), Fig. 4
// (mutation probability) and Fig. 5 (convergence), kept so that the tables, the tests and the
// discussion are all computed from the same runs.

#include <cstddef>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/bpso_vertices_runs.h"
#include "bench/papers/experiment.h"

namespace swarmplan::bench::bpso {

inline constexpr double kSwarmFactors[] = {1.0, 1.5, 2.0};
// Fig. 4's x values are not in our copy of the paper (only its text: "0.1 is a better choice");
// these bracket 0.1 on both sides.
inline constexpr double kMutationProbabilities[] = {0.0,  0.01, 0.02, 0.05, 0.1,
                                                    0.15, 0.2,  0.3,  0.4,  0.5};
inline constexpr int kConvergenceVertices[] = {16, 32};

// Fig. 5's algorithms, in the order of ConvergenceVariants.
enum ConvergenceVariant { kWithMutation, kNoMutation, kPlainBpso, kGa, kConvergenceVariantCount };
struct ConvergenceSpec {
  std::string label;
  PlanSpec spec;
};
std::vector<ConvergenceSpec> ConvergenceVariants(int iterations);

struct ConvergenceWorld {
  size_t world = 0;            // index into FigureRuns::worlds
  std::vector<Runs> variants;  // indexed by ConvergenceVariant
};

struct FigureRuns {
  int runs = 0;                                // per cell
  int iterations = 0;                          // per run
  std::vector<World> worlds;                   // as kVertexCounts
  std::vector<std::vector<Runs>> swarm_sizes;  // [world][as kSwarmFactors], mutation 0.1
  std::vector<std::vector<Runs>> mutations;    // [world][as kMutationProbabilities], N = 1.5 D
  std::vector<ConvergenceWorld> convergence;   // the worlds of kConvergenceVertices
};

// Every run of Table 1, Fig. 4 and Fig. 5 on the shipped worlds.
absl::StatusOr<FigureRuns> RunFigures(const ExperimentOptions& options, int runs, int iterations);

}  // namespace swarmplan::bench::bpso
