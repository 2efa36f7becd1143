#include "core/operators/path_search_planner.h"

#include <limits>
#include <optional>

#include "core/geometry/collision.h"

namespace swarmplan {
namespace {

// Reports the best so far as no worse than a path known before the search: that path is the
// search's incumbent from iteration 0.
class IncumbentObserver final : public Observer {
 public:
  IncumbentObserver(Observer& inner, double known) : inner_(inner), known_(known) {}
  void OnIteration(const IterationStats& stats) override {
    IterationStats reported = stats;
    Apply(reported);
    inner_.OnIteration(reported);
  }
  void Apply(IterationStats& stats) const {
    if (known_ < stats.best_fitness) {
      stats.best_fitness = known_;
      stats.feasible = true;
    }
  }

 private:
  Observer& inner_;
  double known_;
};

}  // namespace

absl::StatusOr<SearchResult> PathSearchPlanner::Solve(const Problem& problem, const StopToken& stop,
                                                      Observer& observer) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("problem has no map");
  absl::StatusOr<std::unique_ptr<PathObjective>> objective = make_objective_(problem);
  if (!objective.ok()) return objective.status();
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*problem.map);
  std::optional<PathObjective::KnownPath> known = (*objective)->BestKnownPath();
  if (known && !checker->PathFree(known->path, problem.clearance)) known.reset();
  IncumbentObserver incumbent(observer,
                              known ? known->fitness : std::numeric_limits<double>::infinity());

  Rng rng(problem.seed);
  const int t_max = PlannedIterations(iterations_, problem.limits);
  absl::StatusOr<SearchOutcome> outcome = optimise_(**objective, t_max, rng, stop, incumbent);
  if (!outcome.ok()) return outcome.status();

  SearchResult result;
  result.fitness = outcome->best_fitness;
  result.iterations = outcome->iterations;
  result.evaluations = outcome->evaluations;
  result.best_iteration = outcome->best_iteration;
  result.stop_reason = outcome->stop_reason;
  result.convergence = std::move(outcome->convergence);
  for (IterationStats& stats : result.convergence) incumbent.Apply(stats);
  if (outcome->best_x.size() == (*objective)->dim() && (*objective)->dim() > 0) {
    Path path = (*objective)->Decode(outcome->best_x);
    result.found = checker->PathFree(path, problem.clearance);
    if (result.found) result.path = std::move(path);
  }
  if (known && (!result.found || known->fitness <= result.fitness)) {
    result.found = true;
    result.path = std::move(known->path);
    result.fitness = known->fitness;
    result.best_iteration = 0;
  }
  return result;
}

}  // namespace swarmplan
