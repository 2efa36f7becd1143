#pragma once

#include <functional>
#include <memory>

#include "absl/status/statusor.h"
#include "core/operators/objective.h"
#include "core/operators/search_loop.h"
#include "core/planner.h"
#include "core/random.h"

namespace swarmplan {

// A swarm planner as a composition: an objective built from the problem (the path encoding
// and fitness) and an optimiser run on it. Solve seeds the Rng from problem.seed, plans
// min(iterations, limits.max_iterations) iterations, decodes the best decision vector into the
// path and reports found = the path is collision-free by the map's CollisionChecker. A path the
// objective knows before the search (BestKnownPath) is the incumbent from iteration 0: the best
// reported per iteration is never worse than it, and it is the result when the search ends on
// nothing better or nothing collision-free. With problem.alternatives > 1 the result also holds
// the best collision-free path of each other corridor of the objective (from the final
// population or the corridor's known path).
class PathSearchPlanner final : public Planner {
 public:
  using ObjectiveFactory =
      std::function<absl::StatusOr<std::unique_ptr<PathObjective>>(const Problem&)>;
  using Optimiser = std::function<absl::StatusOr<SearchOutcome>(
      PathObjective& objective, int t_max, Rng& rng, const StopToken& stop, Observer& observer)>;

  PathSearchPlanner(ObjectiveFactory make_objective, Optimiser optimise, int iterations)
      : make_objective_(std::move(make_objective)),
        optimise_(std::move(optimise)),
        iterations_(iterations) {}

  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override;

 private:
  ObjectiveFactory make_objective_;
  Optimiser optimise_;
  int iterations_;
};

}  // namespace swarmplan
