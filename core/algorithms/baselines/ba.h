#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "core/operators/objective.h"
#include "core/operators/search_loop.h"
#include "core/random.h"

namespace swarmplan {

// The bat algorithm (Yang 2010), the BA baseline of AEM-BSO. Per bat: frequency
// f = f_min + (f_max - f_min) beta; v <- v + (x - x*) f; candidate x + v; with probability
// 1 - r_i the candidate is instead a local walk x* + eps A_avg walk_fraction span (eps in
// [-1, 1] per dimension; the span scaling is ours). A candidate no worse than the bat is kept
// with probability A_i, then A_i <- alpha A_i and r_i <- r0 (1 - exp(-gamma t)). The best bat
// x* follows every candidate no worse than it.

// When a bat's pulse rate r_i follows r0 (1 - exp(-gamma t)).
enum class PulseSchedule {
  kOnAccept,      // r_i starts at r0 and is set to the schedule when bat i accepts a candidate
  kPerIteration,  // every bat's r_i is the schedule at every iteration, from r_i = 0 at t = 0
};

absl::StatusOr<PulseSchedule> ParsePulseSchedule(const std::string& name);

struct BatOptions {
  int population = 100;
  double f_min = 0.0;
  double f_max = 2.0;
  double loudness0 = 1.0;
  double pulse_rate0 = 0.5;
  double alpha = 0.9;
  double gamma = 0.9;
  double walk_fraction = 0.01;
  // Each velocity coordinate is kept within this fraction of its coordinate's span; 0: no bound.
  double velocity_fraction = 0.0;
  PulseSchedule pulse_schedule = PulseSchedule::kOnAccept;
  PositionBound positions = PositionBound::kBox;
};

SearchOutcome RunBatAlgorithm(Objective& objective, const BatOptions& options, int t_max, Rng& rng,
                              const StopToken& stop, Observer& observer);

}  // namespace swarmplan
