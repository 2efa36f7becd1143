#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "core/map/point.h"
#include "core/params.h"
#include "core/problem.h"
#include "core/stop_token.h"

namespace swarmplan {

// One iteration of a search: one generation of the whole population.
struct IterationStats {
  int iteration = 0;          // 0-based
  double best_fitness = 0.0;  // best so far (non-increasing)
  double mean_fitness = 0.0;  // of the population in this iteration
  int64_t evaluations = 0;    // fitness evaluations so far
  absl::Duration elapsed;
  bool feasible = false;  // the best so far is collision-free
};

class Observer {
 public:
  virtual ~Observer() = default;
  virtual void OnIteration(const IterationStats& stats) = 0;
};

class NullObserver final : public Observer {
 public:
  void OnIteration(const IterationStats&) override {}
};

// What a planner's search returns. RunPlan adds smoothing, metrics and timing.
struct SearchResult {
  bool found = false;  // a collision-free path was found
  Path path;           // raw waypoints, start first and goal last; empty when nothing found
  double fitness = 0.0;
  int iterations = 0;
  int64_t evaluations = 0;
  int best_iteration = 0;  // iteration at which the final best was first reached
  StopReason stop_reason = StopReason::kNone;
  std::vector<IterationStats> convergence;
  // The best seed path the search started from, when it had one (the seeded planners):
  // RunPlan smooths and evaluates it beside the result.
  Path seed_path;
  // Other collision-free paths, each in a corridor of its own and none in the path's, best
  // (lowest fitness) first; at most problem.alternatives - 1.
  struct Alternative {
    Path path;
    double fitness = 0.0;
  };
  std::vector<Alternative> alternatives;
};

// The one interface every planner implements. A planner is a value type carrying its validated
// parameters; Solve owns no threads, deadlines or sockets. It checks the stop token and calls
// OnIteration once per iteration, and draws every random number from an Rng seeded with
// problem.seed, so the same problem gives the same result.
class Planner {
 public:
  virtual ~Planner() = default;
  virtual absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                             Observer& observer) = 0;
  // What only this planner can tell about a problem the map-level checks accepted (e.g. that its
  // raster can use the start and goal), without planning: FAILED_PRECONDITION saying what it
  // cannot use. Solve would fail with the same error. The default accepts every problem.
  virtual absl::Status CheckProblem(const Problem& /*problem*/) const { return absl::OkStatus(); }
};

}  // namespace swarmplan
