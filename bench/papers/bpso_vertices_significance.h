#pragma once

// The tests behind the bpso-vertices report's comparisons (bench/papers/comparison.h): whether
// N = 2D beats N = 1D (Table 1), how the best mutation probability compares with the paper's
// 0.1 and the others (Fig. 4), and the paper's variant against the others of Fig. 5.

#include <cstddef>
#include <optional>
#include <vector>

#include "bench/papers/bpso_vertices_figures.h"

namespace swarmplan::bench::bpso {

// Table 1 on one world: N = 2D against N = 1D.
struct SwarmSizeTest {
  size_t world = 0;
  std::optional<double> length_p;          // rank-sum on the found lengths
  std::optional<double> time_p;            // rank-sum on the wall times
  std::optional<double> ours_time_ratio;   // median time 2D / 1D, as the test compares
  std::optional<double> paper_time_ratio;  // the paper's time 2D / 1D
};
std::vector<SwarmSizeTest> TestSwarmSizes(const FigureRuns& figures);

// The paper's time over our mean time in one cell of Table 1.
std::optional<double> PaperOverOurTime(const World& world, double swarm_factor, const Runs& runs);
// Every cell's, in table order.
std::vector<double> PaperOverOurTimes(const FigureRuns& figures);

// Fig. 4 on one world: the best probability (lowest median length, ties broken by the lower
// mean) against each other one.
struct MutationTest {
  size_t world = 0;
  std::optional<size_t> best;                         // index into kMutationProbabilities
  std::vector<std::optional<double>> p_against_best;  // rank-sum on lengths, per probability
  // Per probability: p_against_best < kSignificanceLevel and ranked after the best (a significant
  // difference the other way would be one the ranking missed, and is not counted as worse).
  std::vector<bool> worse_than_best;
  size_t paper = 0;  // index of the paper's 0.1
};
std::vector<MutationTest> TestMutations(const FigureRuns& figures);

// Fig. 5 on one world: every variant against the paper's (double structure + mutation 0.1).
struct ConvergenceTest {
  size_t convergence = 0;                          // index into FigureRuns::convergence
  std::vector<std::optional<double>> length_p;     // rank-sum on final lengths, per variant
  std::vector<std::optional<double>> iteration_p;  // rank-sum on the iteration of the final best
  std::vector<std::optional<double>> success_p;    // Fisher on the found runs
};
std::vector<ConvergenceTest> TestConvergence(const FigureRuns& figures);

}  // namespace swarmplan::bench::bpso
