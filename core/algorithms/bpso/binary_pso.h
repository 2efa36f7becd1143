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
//
// init=seeded (the parameters' default; ours): the candidate vertices are those near the
// corridors of `seeds` exact seed paths (FindSeedPaths) — within each segment's free width
// (capped) plus a margin of the segment, and the seeds' own vertices — ordered by their position
// along the nearest seed, so the particle's length follows the path, not the map. The swarm
// (1.5x the vertices, at most max_swarm) starts from the seeds' bit patterns and perturbations of
// them, the best seed is the incumbent from iteration 0, and the result is never longer than the
// best seed. init=paper: every vertex of the map, ordered along the start-goal line, random initial
// bits, refused above max_vertices. A directly constructed planner runs the paper's.
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
  double assistant_bound = 0.0;     // |assistant position| at most this; 0: unbounded (ours)
  double penalty_factor = 100.0;    // N = factor * the map's diagonal (ours: "very large")
  double circle_tolerance = 0.002;  // circles as polygons, times the world's larger side (ours)
  int max_vertices = 2000;          // init=paper: more vertices are refused (ours)
  bool seeded = false;              // init=seeded (ours)
  int seeds = 3;                    // init=seeded: seed paths (ours)
  int max_swarm = 200;              // init=seeded: the most particles (ours)
  double corridor_cap = 0.02;       // init=seeded: free width counted, times the diagonal (ours)
  double corridor_margin = 0.005;   // init=seeded: margin beyond it, times the diagonal (ours)

  static std::vector<ParamSpec> Specs();
  static BinaryPsoParams From(const ParamSet& set);
};

// An assistant position beyond this magnitude has sigmoid above 0.99 or below 0.01 (ln 99): its
// bit is redrawn against it in fewer than 1 % of updates.
inline constexpr double kSaturatedAssistant = 4.595119850134589;

// What the double structure's assistant positions did, iteration by iteration, for experiments
// that look inside a search (the server never asks for it).
struct AssistantTrace {
  std::vector<double> saturated_fraction;  // of all positions, |x| >= kSaturatedAssistant
  std::vector<double> mean_magnitude;      // mean |x| over all positions
};

class BinaryPsoPlanner final : public Planner {
 public:
  explicit BinaryPsoPlanner(BinaryPsoParams params) : params_(params) {}
  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override;
  // The next Solve records its assistant positions after every iteration into `trace` (cleared
  // first); null stops recording. The trace must outlive the Solve.
  void TraceAssistants(AssistantTrace* trace) { trace_ = trace; }

 private:
  BinaryPsoParams params_;
  AssistantTrace* trace_ = nullptr;
};

// The most candidate vertices a seeded bpso accepts (FAILED_PRECONDITION beyond).
inline constexpr int64_t kMaxSeededBpsoVertices = 100000;

PlannerInfo BinaryPsoInfo();

}  // namespace swarmplan
