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

// Where each iteration stands on the schedules (Iteration::schedule_t). They follow t until a
// quarter of the search's time to the deadline has passed; from then on, while the iterations
// expected to fit by the deadline (at the pace of the faster of the last iteration and their
// mean) are fewer than 90 % of t_max, they run over those instead. A search that has time, even
// one whose first iterations are slow, keeps its schedules as without a deadline.
class ScheduleClock {
 public:
  ScheduleClock(int t_max, absl::Time start, absl::Time deadline)
      : t_max_(t_max), start_(start), deadline_(deadline) {}

  int At(int t) {
    int at = t;
    if (length_ < t_max_) {
      at = static_cast<int>(
          std::min<int64_t>(t_max_ - 1, static_cast<int64_t>(t) * t_max_ / std::max(length_, 1)));
    }
    // Never back: a schedule lengthened again waits at its place until t catches up.
    schedule_t_ = std::max(schedule_t_, at);
    return schedule_t_;
  }

  // After `done` iterations, `elapsed` since the search started.
  void Done(int done, absl::Duration elapsed) {
    const absl::Duration last = elapsed - previous_elapsed_;
    previous_elapsed_ = elapsed;
    if (deadline_ == absl::InfiniteFuture() || elapsed < (deadline_ - start_) / 4) return;
    const double pace = absl::ToDoubleSeconds(std::min(elapsed / done, last));
    if (pace <= 0) return;
    const double remaining = std::max(0.0, absl::ToDoubleSeconds(deadline_ - absl::Now()));
    const double expected = done + std::floor(remaining / pace);
    length_ = expected >= 0.9 * t_max_ ? t_max_ : std::max(done, static_cast<int>(expected));
  }

 private:
  const int t_max_;
  const absl::Time start_, deadline_;
  int length_ = t_max_;  // the schedules' length in iterations
  int schedule_t_ = 0;
  absl::Duration previous_elapsed_;
};

}  // namespace

void RunIterations(int t_max, const StopToken& stop, Observer& observer, SearchOutcome& outcome,
                   const std::function<IterationSummary(const Iteration&)>& iterate) {
  const absl::Time start = absl::Now();
  double logged_best = outcome.best_fitness;
  ScheduleClock schedule(t_max, start, stop.deadline());
  for (int t = 0;; ++t) {
    StopReason reason = stop.Check(t);
    if (reason == StopReason::kNone && t >= t_max) reason = StopReason::kIterationCap;
    if (reason != StopReason::kNone) {
      outcome.stop_reason = reason;
      break;
    }
    Iteration iteration;
    iteration.t = t;
    iteration.schedule_t = schedule.At(t);
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
    schedule.Done(t + 1, stats.elapsed);
  }
}

}  // namespace swarmplan
