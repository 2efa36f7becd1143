#include "core/algorithms/bas/beetle_antennae.h"

#include <cmath>
#include <limits>
#include <vector>

#include "core/operators/antennae.h"

namespace swarmplan {
namespace {

// Draws from C_ini (eq 12): the band widens after every infeasible draw.
Evaluation DrawInitial(Objective& objective, const BeetleAntennaeOptions& options, Rng& rng,
                       Eigen::VectorXd& x, int64_t& evaluations) {
  double band = options.band_step;
  Evaluation e;
  for (int draw = 0; draw < std::max(options.max_initial_draws, 1); ++draw) {
    objective.SampleAroundStraightPath(band, rng, x);
    e = objective.Evaluate(x);
    ++evaluations;
    if (e.feasible) break;
    band += options.band_step;
  }
  return e;
}

void Normalise(Eigen::VectorXd& v, const Eigen::VectorXd& fallback) {
  const double norm = v.norm();
  if (norm > 1e-12) {
    v /= norm;
  } else {
    v = fallback;
  }
}

}  // namespace

SearchOutcome RunBeetleAntennae(Objective& objective, const BeetleAntennaeOptions& options,
                                int t_max, Rng& rng, const StopToken& stop, Observer& observer,
                                const std::optional<Eigen::VectorXd>& seed) {
  const int dim = objective.dim();
  const int n = std::max(options.population, 1);
  SearchOutcome out;
  out.best_fitness = std::numeric_limits<double>::infinity();
  std::vector<Eigen::VectorXd> x(n, Eigen::VectorXd(dim));
  std::vector<Eigen::VectorXd> last_good_dir(n, Eigen::VectorXd::Zero(dim));
  std::vector<double> f(n);
  std::vector<Eigen::VectorXd> guesses;
  if (seed.has_value()) {
    guesses.push_back(*seed);
  } else {
    guesses = objective.InitialGuesses();
  }
  for (int j = 0; j < n; ++j) {
    Evaluation e;
    if (!guesses.empty()) {
      x[j] = guesses[j % guesses.size()];
      objective.Clamp(x[j]);
      e = objective.Evaluate(x[j]);
      ++out.evaluations;
    } else {
      e = DrawInitial(objective, options, rng, x[j], out.evaluations);
    }
    f[j] = e.fitness;
    if (j == 0 || e.fitness < out.best_fitness) {
      out.best_fitness = e.fitness;
      out.best_x = x[j];
      out.best_feasible = e.feasible;
    }
  }

  double delta = options.step0;
  double theta = options.theta0;
  // World units per unit of b: the coordinates' ranges, or 1 (the paper's steps).
  const Eigen::VectorXd scale = options.relative_steps
                                    ? Eigen::VectorXd(objective.upper() - objective.lower())
                                    : Eigen::VectorXd::Ones(dim);
  // 1 / scale, 0 on a coordinate with no range (it never moves).
  const Eigen::VectorXd inv_scale =
      scale.unaryExpr([](double s) { return s > 0.0 ? 1.0 / s : 0.0; });
  Eigen::VectorXd b(dim), b1(dim), w(dim), scratch(dim), candidate(dim), previous(dim);

  auto consider = [&](const Eigen::VectorXd& point, const Evaluation& e) {
    if (e.fitness >= out.best_fitness) return false;
    out.best_fitness = e.fitness;
    out.best_x = point;
    out.best_feasible = e.feasible;
    return true;
  };
  // Local fast search around the best (eqs 9-11); the main step is untouched.
  auto local_fast_search = [&]() {
    double step = delta;
    for (int i = 0; i < options.lfs_steps; ++i) {
      b1 = rng.UnitDirection(dim);
      w = scale.cwiseProduct(b1);
      const AntennaeProbe probe = ProbeAntennae(objective, out.best_x, w, step, scratch);
      candidate = out.best_x;
      AddAntennaeStep(probe, w, step, candidate);
      objective.Clamp(candidate);
      objective.Repair(theta, candidate);
      const Evaluation e = objective.Evaluate(candidate);
      out.evaluations += 3;
      if (e.feasible || !options.reject_infeasible) consider(candidate, e);
      step *= std::pow(options.lfs_lambda,
                       options.lfs_b / (options.lfs_a + options.lfs_gamma * i / options.lfs_steps));
    }
  };

  RunIterations(t_max, stop, observer, out, [&](const Iteration&) {
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
      b1 = rng.UnitDirection(dim);
      b = options.eta1 * b1;
      if (options.eta2 != 0.0) {
        Eigen::VectorXd to_best = (out.best_x - x[j]).cwiseProduct(inv_scale);
        const double norm = to_best.norm();
        if (norm > 1e-12) b += (options.eta2 / norm) * to_best;
      }
      if (options.eta3 != 0.0) b += options.eta3 * last_good_dir[j];
      Normalise(b, b1);
      if (options.pso_mix) {
        for (int k = 0; k < dim; ++k) {
          b[k] = options.pso_m * b[k] +
                 options.pso_c1 * ((out.best_x[k] - x[j][k]) * inv_scale[k]) * rng.Uniform();
        }
        Normalise(b, b1);
      }
      w = scale.cwiseProduct(b);
      const AntennaeProbe probe = ProbeAntennae(objective, x[j], w, delta / options.c, scratch);
      if (options.reject_infeasible) previous = x[j];
      AddAntennaeStep(probe, w, delta, x[j]);
      last_good_dir[j] = probe.toward_right * b;
      objective.Clamp(x[j]);
      objective.Repair(theta, x[j]);
      const Evaluation e = objective.Evaluate(x[j]);
      out.evaluations += 3;
      if (!e.feasible && options.reject_infeasible) {
        x[j] = previous;  // f[j] is still its fitness
        sum += f[j];
        continue;
      }
      f[j] = e.fitness;
      sum += e.fitness;
      if (consider(x[j], e) && options.lfs_steps > 0) local_fast_search();
    }
    delta *= options.step_decay;
    theta *= options.theta_decay;
    return IterationSummary{sum / n};
  });
  return out;
}

}  // namespace swarmplan
