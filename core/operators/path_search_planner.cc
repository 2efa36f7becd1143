#include "core/operators/path_search_planner.h"

#include <algorithm>
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

// The best collision-free path of every corridor but `taken`, from the final population and the
// corridor's known path, best first, at most `count`.
std::vector<SearchResult::Alternative> Alternatives(PathObjective& objective,
                                                    const SearchOutcome& outcome, int taken,
                                                    int count, const CollisionChecker& checker,
                                                    double clearance) {
  // Exact checks per corridor at most: members beyond them are not worth the time.
  constexpr int kTriesPerCorridor = 4;
  std::vector<int> order(outcome.population.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return outcome.population_fitness[a] < outcome.population_fitness[b];
  });
  std::vector<SearchResult::Alternative> found;
  for (int corridor = 0; corridor < objective.Corridors(); ++corridor) {
    if (corridor == taken) continue;
    std::optional<SearchResult::Alternative> best;
    if (std::optional<PathObjective::KnownPath> known = objective.KnownPathIn(corridor);
        known && checker.PathFree(known->path, clearance)) {
      best = SearchResult::Alternative{std::move(known->path), known->fitness};
    }
    int tries = 0;
    for (int i : order) {
      if (tries == kTriesPerCorridor) break;
      if (objective.CorridorOf(outcome.population[i]) != corridor) continue;
      if (best && best->fitness <= outcome.population_fitness[i]) break;
      ++tries;
      Path path = objective.Decode(outcome.population[i]);
      if (checker.PathFree(path, clearance)) {
        best = SearchResult::Alternative{std::move(path), outcome.population_fitness[i]};
        break;
      }
    }
    if (best) found.push_back(*std::move(best));
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.fitness < b.fitness; });
  if (static_cast<int>(found.size()) > count) found.resize(count);
  return found;
}

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
  if (known) result.seed_path = known->path;
  result.fitness = outcome->best_fitness;
  result.iterations = outcome->iterations;
  result.evaluations = outcome->evaluations;
  result.best_iteration = outcome->best_iteration;
  result.stop_reason = outcome->stop_reason;
  result.convergence = std::move(outcome->convergence);
  for (IterationStats& stats : result.convergence) incumbent.Apply(stats);
  int corridor = -1;
  if (outcome->best_x.size() == (*objective)->dim() && (*objective)->dim() > 0) {
    Path path = (*objective)->Decode(outcome->best_x);
    result.found = checker->PathFree(path, problem.clearance);
    if (result.found) {
      result.path = std::move(path);
      corridor = (*objective)->CorridorOf(outcome->best_x);
    }
  }
  if (known && (!result.found || known->fitness <= result.fitness)) {
    result.found = true;
    result.path = std::move(known->path);
    result.fitness = known->fitness;
    result.best_iteration = 0;
    corridor = (*objective)->BestKnownCorridor();
  }
  if (result.found && problem.alternatives > 1) {
    result.alternatives = Alternatives(**objective, *outcome, corridor, problem.alternatives - 1,
                                       *checker, problem.clearance);
  }
  return result;
}

}  // namespace swarmplan
