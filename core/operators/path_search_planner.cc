#include "core/operators/path_search_planner.h"

#include "core/geometry/collision.h"

namespace swarmplan {

absl::StatusOr<SearchResult> PathSearchPlanner::Solve(const Problem& problem, const StopToken& stop,
                                                      Observer& observer) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("problem has no map");
  absl::StatusOr<std::unique_ptr<PathObjective>> objective = make_objective_(problem);
  if (!objective.ok()) return objective.status();
  Rng rng(problem.seed);
  const int t_max = PlannedIterations(iterations_, problem.limits);
  absl::StatusOr<SearchOutcome> outcome = optimise_(**objective, t_max, rng, stop, observer);
  if (!outcome.ok()) return outcome.status();

  SearchResult result;
  result.fitness = outcome->best_fitness;
  result.iterations = outcome->iterations;
  result.evaluations = outcome->evaluations;
  result.best_iteration = outcome->best_iteration;
  result.stop_reason = outcome->stop_reason;
  result.convergence = std::move(outcome->convergence);
  if (outcome->best_x.size() == (*objective)->dim() && (*objective)->dim() > 0) {
    Path path = (*objective)->Decode(outcome->best_x);
    result.found = MakeCollisionChecker(*problem.map)->PathFree(path, problem.clearance);
    if (result.found) result.path = std::move(path);
  }
  return result;
}

}  // namespace swarmplan
