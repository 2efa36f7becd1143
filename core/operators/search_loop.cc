#include "core/operators/search_loop.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "absl/time/clock.h"

namespace swarmplan {

int PlannedIterations(int param, const Limits& limits) {
  return limits.max_iterations > 0 ? std::min(param, limits.max_iterations) : param;
}

namespace {

// The iterations a search is expected to complete by `deadline` after `done` of them took
// `elapsed`, at most `t_max`.
int ExpectedIterations(int t_max, int done, absl::Duration elapsed, absl::Time deadline) {
  if (deadline == absl::InfiniteFuture() || done <= 0 || elapsed <= absl::ZeroDuration()) {
    return t_max;
  }
  const double per_iteration = absl::ToDoubleSeconds(elapsed) / done;
  const double remaining = std::max(0.0, absl::ToDoubleSeconds(deadline - absl::Now()));
  const double expected = done + std::floor(remaining / per_iteration);
  return expected >= t_max ? t_max : std::max(done, static_cast<int>(expected));
}

}  // namespace

void RunIterations(int t_max, const StopToken& stop, Observer& observer, SearchOutcome& outcome,
                   const std::function<IterationSummary(const Iteration&)>& iterate) {
  const absl::Time start = absl::Now();
  double logged_best = outcome.best_fitness;
  // The schedules' length: t_max, shortened (never lengthened again) while the deadline is
  // expected to come first.
  int schedule_length = t_max;
  for (int t = 0;; ++t) {
    StopReason reason = stop.Check(t);
    if (reason == StopReason::kNone && t >= t_max) reason = StopReason::kIterationCap;
    if (reason != StopReason::kNone) {
      outcome.stop_reason = reason;
      break;
    }
    Iteration iteration;
    iteration.t = t;
    iteration.schedule_t =
        schedule_length == t_max
            ? t
            : static_cast<int>(std::min<int64_t>(
                  t_max - 1, static_cast<int64_t>(t) * t_max / std::max(schedule_length, 1)));
    const IterationSummary summary = iterate(iteration);
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
    schedule_length =
        std::min(schedule_length, ExpectedIterations(t_max, t + 1, stats.elapsed, stop.deadline()));
  }
}

}  // namespace swarmplan
