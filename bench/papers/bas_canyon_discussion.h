#pragma once

// The discussion of the bas-canyon report, computed from its runs: every figure it quotes comes
// from the runs, and every difference it names comes with a test at p < kSignificanceLevel.

#include <string>
#include <vector>

#include "bench/papers/bas_canyon_replicated.h"
#include "bench/papers/bas_canyon_runs.h"
#include "bench/papers/bas_canyon_significance.h"
#include "bench/papers/bas_canyon_sweeps.h"

namespace swarmplan::bench::bas {

struct DiscussionInputs {
  RowSet shipped;                                 // every row run on the shipped canyon
  double yardstick = 0.0;                         // its lattice optimum
  std::vector<std::string> paper_setting_labels;  // beetle rows with the paper's δ0 = 8 cells
  std::vector<PairTest> headline;                 // the paper's claims (Tables A and B)
  std::vector<PairTest> options;                  // our step options (Table D)
  std::vector<std::string> step_labels;           // Table C's rows
  RowSet sweep_set;                               // Table 3's rows
  std::vector<PairTest> sweep;                    // Table 3
  MovedStartTest moved_start;                     // Fig. 6
  std::vector<ReplicatedPairTest> replicated;
  int replicated_worlds = 0;
  int dimensions = 0;  // coordinates of the beetle's decision vector
};

std::string Discussion(const DiscussionInputs& in);

}  // namespace swarmplan::bench::bas
