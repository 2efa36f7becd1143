// RunIterations: the iteration cap, and the schedules' place per iteration with and without a
// deadline.
#include "core/operators/search_loop.h"

#include <algorithm>
#include <thread>
#include <vector>

#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

// The iterations RunIterations hands out; each takes `pace` (the first `first_pace`).
std::vector<Iteration> Iterations(int t_max, const StopToken& stop, absl::Duration pace,
                                  absl::Duration first_pace = absl::ZeroDuration()) {
  std::vector<Iteration> seen;
  SearchOutcome outcome;
  NullObserver observer;
  RunIterations(t_max, stop, observer, outcome, [&](const Iteration& iteration) {
    seen.push_back(iteration);
    const absl::Duration wait = iteration.t == 0 ? std::max(pace, first_pace) : pace;
    if (wait > absl::ZeroDuration()) std::this_thread::sleep_for(absl::ToChronoNanoseconds(wait));
    return IterationSummary{};
  });
  EXPECT_EQ(outcome.iterations, static_cast<int>(seen.size()));
  return seen;
}

// Without a deadline, or with one that leaves time for every iteration (even after a first
// iteration slow enough that its pace alone would not), the schedules follow the iteration
// count: the same seed gives the same search.
TEST(SearchLoopTest, SchedulesFollowTheIterationsWhenTheDeadlineLeavesRoom) {
  for (const StopToken& stop : {StopToken(), StopToken().WithDeadline(absl::Now() + absl::Hours(1)),
                                StopToken().WithDeadline(absl::Now() + absl::Seconds(30))}) {
    const std::vector<Iteration> seen =
        Iterations(200, stop, absl::ZeroDuration(), absl::Milliseconds(300));
    ASSERT_EQ(seen.size(), 200u);
    for (int t = 0; t < 200; ++t) {
      EXPECT_EQ(seen[t].t, t);
      EXPECT_EQ(seen[t].schedule_t, t);
    }
  }
}

// A deadline that ends the search long before t_max: the schedules run over the iterations
// that fit, rising monotonically from 0 to near their end by the last iteration.
TEST(SearchLoopTest, SchedulesSpanTheIterationsThatFitBeforeTheDeadline) {
  constexpr int kTMax = 100000;
  const StopToken stop = StopToken().WithDeadline(absl::Now() + absl::Milliseconds(200));
  const std::vector<Iteration> seen = Iterations(kTMax, stop, absl::Milliseconds(2));
  ASSERT_GE(seen.size(), 5u);
  ASSERT_LT(seen.size(), static_cast<size_t>(kTMax));
  EXPECT_EQ(seen.front().schedule_t, 0);
  for (size_t i = 1; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].t, static_cast<int>(i));
    EXPECT_GE(seen[i].schedule_t, seen[i - 1].schedule_t);
    EXPECT_LT(seen[i].schedule_t, kTMax);
  }
  // The last iteration lies in the schedules' last half (at an even pace, near their end).
  EXPECT_GE(seen.back().schedule_t, kTMax / 2);
}

}  // namespace
}  // namespace swarmplan
