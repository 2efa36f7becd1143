#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/planner.h"
#include "core/problem.h"
#include "core/stop_token.h"

namespace swarmplan {

// What an optimiser found: the best decision vector and the search's log.
struct SearchOutcome {
  Eigen::VectorXd best_x;
  double best_fitness = 0.0;
  bool best_feasible = false;
  int iterations = 0;
  int64_t evaluations = 0;
  int best_iteration = 0;
  StopReason stop_reason = StopReason::kNone;
  std::vector<IterationStats> convergence;
  // The final population (each member's best for the swarms that keep one) and its fitness,
  // for the planners that offer alternatives; empty when an optimiser does not report it.
  std::vector<Eigen::VectorXd> population;
  std::vector<double> population_fitness;
};

// What one iteration reports to the loop.
struct IterationSummary {
  double mean_fitness = 0.0;  // of the population in this iteration
};

// One iteration, as the loop hands it to a search.
struct Iteration {
  int t = 0;  // 0-based
  // t on the scale of the schedules that run over t_max iterations (inertia weights, the elite
  // mutation): t itself, unless the stop token's deadline is expected to end the search well
  // before t_max; then the schedules run over the iterations expected to fit, so the search
  // reaches their end (small steps about its best) before its time is up. Never decreasing.
  int schedule_t = 0;
};

// The iteration count a planner plans with: its own parameter, lowered by the problem's cap.
int PlannedIterations(int param, const Limits& limits);

// Runs `iterate` for t = 0, 1, ... until `t_max` iterations are done or the stop token says
// stop (checked before every iteration). After each iteration it records the best so far from
// `outcome` (which `iterate` keeps up to date), keeps it non-increasing, and calls the observer.
void RunIterations(int t_max, const StopToken& stop, Observer& observer, SearchOutcome& outcome,
                   const std::function<IterationSummary(const Iteration&)>& iterate);

}  // namespace swarmplan
