#pragma once

#include <string>
#include <vector>

#include "core/grid_ops/grid_moves.h"
#include "core/grid_ops/grid_planner.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/registry.h"

namespace swarmplan {

// The artificial fish swarm family on grids (Li, Du & Jia, seed 003), one implementation whose
// variants are parameters:
//   afsa:   4-, 8- or 24-neighbourhood; a move only needs a free target cell (the paper's
//           traditional AFSA may jump over obstacles or cut corners; such paths are reported
//           as not collision-free).
//   dafsa:  24-neighbourhood, every move's segment checked (touches no blocked cell).
//   idafsa: dafsa + feasible-solution set (fish that reach the goal record their trail and
//           start again; the answer is the shortest record), dynamic feedback visual (eq 9) and
//           adaptive step (eqs 10-11).
// Food concentration is the Euclidean distance to the goal. Behaviours: follow and swarm when a
// better, uncrowded (n_f/N <= δ) place is in view, else prey (try_number random cells in view,
// with the paper's culled factor: a tried or unusable cell is not drawn again), else a random
// move. Stepping toward a target (move=direction, eqs 3-5): among the valid moves that get closer
// to it, the one nearest to X + rand()·step·(X_j − X)/||X_j − X||; move=random-closer: a random
// one of them. Valid moves per cell are computed once and shared by all fish.
// init=seeded: fish start spread along the seeds' cell paths, their trails the seed up to there
// (every variant records each arrival and restarts the fish the same way, as idafsa's
// feasible-solution set does: a fish that starts on a seed first arrives along the seed's own
// tail, so the first arrival would be the seed); visual and steps are in cells of a
// 20 x 20 grid (the paper's larger) and scale with the grid's longer side; a fish whose target
// is in line of sight (clipped to its step) swims straight to it; trails are ranked by their
// any-angle length, and the result is never longer than the best seed.
struct FishSwarmParams {
  // How a fish steps toward its target: along eqs 3-5's direction, or to any closer cell.
  enum class Move { kDirection, kRandomCloser };

  Neighbourhood neighbourhood = Neighbourhood::k8;
  bool segment_check = false;
  bool feasible_solutions = false;
  bool dynamic_visual = false;
  bool adaptive_step = false;
  Move move = Move::kDirection;
  bool prey_culling = false;
  int population = 50;  // N
  int try_number = 8;
  int max_generations = 100;             // MAXGEN
  double visual = 5.0;                   // visual (visual_max for idafsa), cells
  double crowding = 0.618;               // δ
  double step_min = 1.4142135623730951;  // cells
  double step_max = 2.8284271247461903;  // cells
  double feedback_gain = 17.0;           // m of eq 9 (17 on 10x10, 10 on 20x20)
  double resolution = 0.0;               // cell size on shape worlds; 0: automatic (ours)
  GridSeeding seeding;

  enum class Variant { kAfsa, kDafsa, kIdafsa };
  static FishSwarmParams Defaults(Variant variant);
  static std::vector<ParamSpec> Specs(Variant variant);
  static FishSwarmParams From(const ParamSet& set);
};

absl::StatusOr<SearchResult> RunGridSearch(const FishSwarmParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer);
using FishSwarmPlanner = GridPlanner<FishSwarmParams>;

PlannerInfo AfsaInfo();
PlannerInfo DafsaInfo();
PlannerInfo IdafsaInfo();

}  // namespace swarmplan
