#pragma once

// The IDAFSA reproduction's ablation of the fish moves: every configuration run again with the
// planner's earlier moves (a random valid move closer to the target, prey search without the
// culled factor), and the paper's per-claim verdicts for idafsa held against the ones those
// moves give.

#include <string>
#include <vector>

#include "bench/papers/idafsa_grids_runs.h"
#include "bench/papers/idafsa_grids_significance.h"

namespace swarmplan::bench {

// `config` with the planner's earlier moves: move=random-closer, prey_culling=false.
FishConfig WithRandomCloserMoves(const FishConfig& config);

// The paper's claims tested in one place, e.g. "10 x 10, shipped world" or "20 x 20, across
// worlds".
struct VerdictScope {
  std::string scope;
  std::vector<ClaimTests> claims;
};

// Per scope, claim and baseline: the outcome with the paper's moves and with the random-closer
// moves, and whether it changed. `paper` and `random_closer` hold the same scopes, claims and
// baselines in the same order. `summary` receives the discussion's sentence on the changes.
std::string MovesVerdictSection(const std::vector<VerdictScope>& paper,
                                const std::vector<VerdictScope>& random_closer,
                                std::string* summary);

}  // namespace swarmplan::bench
