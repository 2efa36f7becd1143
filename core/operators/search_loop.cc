#include "core/operators/search_loop.h"

#include <algorithm>

#include "absl/time/clock.h"

namespace swarmplan {

int PlannedIterations(int param, const Limits& limits) {
  return limits.max_iterations > 0 ? std::min(param, limits.max_iterations) : param;
}

void RunIterations(int t_max, const StopToken& stop, Observer& observer, SearchOutcome& outcome,
                   const std::function<IterationSummary(int)>& iterate) {
  const absl::Time start = absl::Now();
  double logged_best = outcome.best_fitness;
  for (int t = 0;; ++t) {
    StopReason reason = stop.Check(t);
    if (reason == StopReason::kNone && t >= t_max) reason = StopReason::kIterationCap;
    if (reason != StopReason::kNone) {
      outcome.stop_reason = reason;
      break;
    }
    const IterationSummary summary = iterate(t);
    if (t == 0 || outcome.best_fitness < logged_best) {
      if (t > 0) outcome.best_iteration = t;
      logged_best = outcome.best_fitness;
    }
    IterationStats stats;
    stats.iteration = t;
    stats.best_fitness = logged_best;
    stats.mean_fitness = summary.mean_fitness;
    stats.evaluations = outcome.evaluations;
    stats.elapsed = absl::Now() - start;
    stats.feasible = outcome.best_feasible;
    outcome.convergence.push_back(stats);
    outcome.iterations = t + 1;
    observer.OnIteration(stats);
  }
}

}  // namespace swarmplan
