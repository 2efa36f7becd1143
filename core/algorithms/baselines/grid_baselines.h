#pragma once

#include <vector>

#include "core/grid_ops/grid_planner.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/registry.h"

namespace swarmplan {

// The grid baselines the AS-BFO and fish swarm papers compare against. All move on the
// 8-connected grid without corner cutting (a parameter allows it) and plan on shape worlds
// rasterised at `resolution`.

// GA on cell paths: initial paths through random cells joined by A*; roulette selection on
// 1/length; crossover at a shared cell; mutation re-routes a random sub-path through a random
// nearby cell with A*; loops removed; the best individual survives. init=seeded: the initial
// individuals are the seeds' cell paths, mutated once beyond the first of each seed.
struct GridGaParams {
  int population = 50;                 // ours (the AS-BFO paper tuned but did not publish them)
  int generations = 100;               // ours
  double crossover_probability = 0.8;  // ours
  double mutation_probability = 0.2;   // ours
  int mutation_radius = 3;             // cells around the sub-path's middle (ours)
  int max_waypoints = 3;               // ours
  bool allow_corner_cutting = false;
  double resolution = 0.0;  // shape-world cell size; 0: automatic (ours)
  GridSeeding seeding;

  static std::vector<ParamSpec> Specs();
  static GridGaParams From(const ParamSet& set);
};

absl::StatusOr<SearchResult> RunGridSearch(const GridGaParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer);
using GridGaPlanner = GridPlanner<GridGaParams>;

// Ant colony on the grid: each ant walks from the start without revisiting cells, choosing the
// next cell with probability ∝ τ^α η^β, η = 1 / distance to the goal; ants that get stuck die.
// Pheromone lives on directed moves: τ ← (1 − ρ)τ, then each arriving ant adds Q / length.
// init=seeded: the seeds' cell paths are the arrivals of iteration 0 and Q is scaled by the best
// seed's length (so a path as long as it adds Q per move, on every map size).
struct GridAcoParams {
  int ants = 50;
  double alpha = 1.0;
  double beta = 7.0;
  double rho = 0.3;
  double q = 1.0;
  int iterations = 100;  // ours
  double tau0 = 1.0;     // ours
  bool allow_corner_cutting = false;
  double resolution = 0.0;  // shape-world cell size; 0: automatic (ours)
  GridSeeding seeding;

  static std::vector<ParamSpec> Specs();
  static GridAcoParams From(const ParamSet& set);
};

absl::StatusOr<SearchResult> RunGridSearch(const GridAcoParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer);
using GridAcoPlanner = GridPlanner<GridAcoParams>;

// Artificial potential field: steepest descent over the 8 neighbours of
// U = ½ k_att d² + ½ k_rep (1/ρ − 1/ρ0)² (ρ < ρ0; d the distance to the goal, ρ the clearance,
// both in cells). One iteration is one step. It stalls in local minima and then reports no path
// (found = false, stop reason none, fewer iterations than max_steps).
struct GridApfParams {
  double k_att = 1.0;      // ours
  double k_rep = 100.0;    // ours
  double influence = 3.0;  // ρ0, cells (ours)
  int max_steps = 100000;  // ours
  bool allow_corner_cutting = false;
  double resolution = 0.0;  // shape-world cell size; 0: automatic (ours)

  static std::vector<ParamSpec> Specs();
  static GridApfParams From(const ParamSet& set);
};

absl::StatusOr<SearchResult> RunGridSearch(const GridApfParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer);
using GridApfPlanner = GridPlanner<GridApfParams>;

PlannerInfo GridGaInfo();
PlannerInfo GridAcoInfo();
PlannerInfo GridApfInfo();

}  // namespace swarmplan
