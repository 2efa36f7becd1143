#pragma once

#include <vector>

#include "core/grid_ops/grid_planner.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/registry.h"

namespace swarmplan {

// AS-BFO (Long et al., seed 001): bacterial foraging on an 8-connected grid. A bacterium is a
// variable-length cell path from start to goal. Chemotaxis tumbles a random interior cell to a
// random usable neighbour, repairs the gaps to its neighbours with A* and removes loops; the
// swim repeats the same tumble direction while it shortens the path (at most Ns times).
// Reproduction keeps the healthier half (lower accumulated length); elimination-dispersal
// replaces each bacterium with a new random path with probability Ped. init=seeded: bacteria
// start from the seeds' cell paths (one tumble beyond the first of each seed), dispersal returns
// a bacterium to a random seed, and health is the any-angle length.
struct AsBfoParams {
  int population = 50;
  int chemotactic_steps = 5;              // Nc
  int reproduction_steps = 2;             // Nre
  int elimination_steps = 2;              // Ned
  int swim_length = 4;                    // Ns (ours)
  double elimination_probability = 0.25;  // Ped (ours)
  int max_waypoints = 3;                  // random cells an initial path passes through (ours)
  bool keep_worse_tumbles = true;         // classic BFO moves even when the tumble is worse (ours)
  bool allow_corner_cutting = false;
  double resolution = 0.0;  // cell size when planning on a shape world; 0: automatic (ours)
  GridSeeding seeding;

  static std::vector<ParamSpec> Specs();
  static AsBfoParams From(const ParamSet& set);
};

absl::StatusOr<SearchResult> RunGridSearch(const AsBfoParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer);
using AsBfoPlanner = GridPlanner<AsBfoParams>;

PlannerInfo AsBfoInfo();

}  // namespace swarmplan
