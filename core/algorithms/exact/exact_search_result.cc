#include "core/algorithms/exact/exact_search_result.h"

#include <utility>

#include "absl/time/clock.h"
#include "core/path_metrics.h"

namespace swarmplan {

SearchResult FinishExactSearch(Path path, int64_t expanded, absl::Time started,
                               Observer& observer) {
  const double length = PathLength(path);
  return FinishExactSearch(std::move(path), length, expanded, started, observer);
}

SearchResult FinishExactSearch(Path path, double cost, int64_t expanded, absl::Time started,
                               Observer& observer) {
  SearchResult result;
  result.found = !path.empty();
  result.path = std::move(path);
  result.fitness = result.found ? cost : 0.0;
  result.iterations = 1;
  result.evaluations = expanded;
  IterationStats stats;
  stats.iteration = 0;
  stats.best_fitness = result.fitness;
  stats.mean_fitness = result.fitness;
  stats.evaluations = expanded;
  stats.elapsed = absl::Now() - started;
  stats.feasible = result.found;
  observer.OnIteration(stats);
  result.convergence.push_back(stats);
  return result;
}

SearchResult StoppedExactSearch(StopReason reason) {
  SearchResult result;
  result.stop_reason = reason;
  return result;
}

}  // namespace swarmplan
