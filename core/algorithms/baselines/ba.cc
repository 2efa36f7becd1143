#include "core/algorithms/baselines/ba.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"

namespace swarmplan {

absl::StatusOr<PulseSchedule> ParsePulseSchedule(const std::string& name) {
  if (name == "on-accept") return PulseSchedule::kOnAccept;
  if (name == "per-iteration") return PulseSchedule::kPerIteration;
  return absl::InvalidArgumentError(
      absl::StrCat("pulse_schedule: unknown '", name, "' (on-accept or per-iteration)"));
}

SearchOutcome RunBatAlgorithm(Objective& objective, const BatOptions& options, int t_max, Rng& rng,
                              const StopToken& stop, Observer& observer) {
  const int dim = objective.dim();
  const int n = options.population;
  const Eigen::VectorXd span = objective.upper() - objective.lower();
  std::vector<Eigen::VectorXd> x(n, Eigen::VectorXd(dim));
  std::vector<Eigen::VectorXd> v(n, Eigen::VectorXd::Zero(dim));
  const bool per_iteration = options.pulse_schedule == PulseSchedule::kPerIteration;
  const double scheduled_pulse0 = per_iteration ? 0.0 : options.pulse_rate0;
  std::vector<double> f(n), loudness(n, options.loudness0), pulse_rate(n, scheduled_pulse0);
  const bool bounded = options.velocity_fraction > 0.0;
  const Eigen::VectorXd v_max = options.velocity_fraction * span;

  SearchOutcome out;
  out.best_fitness = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < dim; ++j) x[i][j] = rng.Uniform(objective.lower()[j], objective.upper()[j]);
  }
  PlaceInitialGuesses(objective, rng, x);
  for (int i = 0; i < n; ++i) {
    const Evaluation e = objective.Evaluate(x[i]);
    f[i] = e.fitness;
    if (i == 0 || e.fitness < out.best_fitness) {
      out.best_fitness = e.fitness;
      out.best_x = x[i];
      out.best_feasible = e.feasible;
    }
  }
  out.evaluations = n;

  Eigen::VectorXd candidate(dim);
  RunIterations(t_max, stop, observer, out, [&](const Iteration& iteration) {
    const double scheduled_pulse =
        options.pulse_rate0 * (1.0 - std::exp(-options.gamma * iteration.t));
    if (per_iteration) std::fill(pulse_rate.begin(), pulse_rate.end(), scheduled_pulse);
    double mean_loudness = 0.0;
    for (double a : loudness) mean_loudness += a;
    mean_loudness /= std::max(n, 1);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double freq = options.f_min + (options.f_max - options.f_min) * rng.Uniform();
      v[i] += (x[i] - out.best_x) * freq;
      if (bounded) v[i] = v[i].cwiseMax(-v_max).cwiseMin(v_max);
      candidate = x[i] + v[i];
      if (rng.Uniform() > pulse_rate[i]) {
        for (int j = 0; j < dim; ++j) {
          candidate[j] = out.best_x[j] +
                         rng.Uniform(-1.0, 1.0) * mean_loudness * options.walk_fraction * span[j];
        }
      }
      objective.Bound(options.positions, candidate);
      const Evaluation e = objective.Evaluate(candidate);
      ++out.evaluations;
      if (e.fitness <= f[i] && rng.Uniform() < loudness[i]) {
        x[i] = candidate;
        f[i] = e.fitness;
        loudness[i] *= options.alpha;
        if (!per_iteration) pulse_rate[i] = scheduled_pulse;
      }
      if (e.fitness <= out.best_fitness) {
        out.best_fitness = e.fitness;
        out.best_x = candidate;
        out.best_feasible = e.feasible;
      }
      sum += f[i];
    }
    return IterationSummary{n > 0 ? sum / n : 0.0};
  });
  out.population = std::move(x);
  out.population_fitness = std::move(f);
  return out;
}

}  // namespace swarmplan
