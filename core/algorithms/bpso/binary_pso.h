#pragma once

#include <vector>

#include "core/params.h"
#include "core/planner.h"
#include "core/registry.h"

namespace swarmplan {

// Binary PSO over obstacle vertices (Zhang & Gu, seed 004). A particle holds one bit per
// vertex of the obstacles grown by the clearance (on grids: the free cell diagonally outside
// each convex corner of the blocked region); the path runs start -> chosen vertices ordered by
// their projection on the start-goal line -> goal. Fitness (eq 9): length, plus a penalty
// when some segment enters an obstacle. The improved algorithm (default) keeps a continuous
// assistant position per particle (eqs 6-7) and mutates bits; plain BPSO (eqs 1-2) is
// double_structure = false with mutation_probability = 0.
struct BinaryPsoParams {
  bool double_structure = true;
  double mutation_probability = 0.1;
  double swarm_factor = 1.5;  // swarm = ceil(factor * vertex count)
  int iterations = 100;
  double c1 = 2.0;
  double c2 = 2.0;
  double w_max = 0.9;
  double w_min = 0.4;
  double v_max = 4.0;               // ours
  double penalty_factor = 100.0;    // N = factor * the map's diagonal (ours: "very large")
  double circle_tolerance = 0.002;  // circles as polygons, times the world's larger side (ours)
  int max_vertices = 2000;          // more vertices are refused: the swarm grows with them (ours)

  static std::vector<ParamSpec> Specs();
  static BinaryPsoParams From(const ParamSet& set);
};

class BinaryPsoPlanner final : public Planner {
 public:
  explicit BinaryPsoPlanner(BinaryPsoParams params) : params_(params) {}
  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override;

 private:
  BinaryPsoParams params_;
};

PlannerInfo BinaryPsoInfo();

}  // namespace swarmplan
