#include "core/algorithms/bso/beetle_swarm.h"

#include <vector>

#include "core/operators/antennae.h"
#include "core/operators/good_point_set.h"

namespace swarmplan {

SearchOutcome RunBeetleSwarm(Objective& objective, const BeetleSwarmOptions& options, int t_max,
                             Rng& rng, const StopToken& stop, Observer& observer) {
  const int dim = objective.dim();
  const int n = options.population;
  const Eigen::VectorXd span = objective.upper() - objective.lower();
  const Eigen::VectorXd v_max = options.velocity_fraction * span;
  double delta = options.step_fraction * (dim > 0 ? span.mean() : 0.0);

  std::vector<Eigen::VectorXd> x;
  if (options.good_point_init) {
    x = GoodPointSet(n, objective.lower(), objective.upper());
  } else {
    x.resize(n);
    for (auto& xi : x) {
      xi.resize(dim);
      for (int j = 0; j < dim; ++j) xi[j] = rng.Uniform(objective.lower()[j], objective.upper()[j]);
    }
  }
  PlaceInitialGuesses(objective, rng, x);
  std::vector<Eigen::VectorXd> v(n, Eigen::VectorXd::Zero(dim));
  std::vector<Eigen::VectorXd> pbest = x;
  std::vector<double> f(n), f_pbest(n);
  std::vector<bool> feasible_pbest(n);

  SearchOutcome out;
  out.best_fitness = std::numeric_limits<double>::infinity();
  // The initial population in one call.
  Eigen::MatrixXd population(dim, n);
  for (int i = 0; i < n; ++i) population.col(i) = x[i];
  std::vector<Evaluation> initial(n);
  objective.EvaluateColumns(population, initial.data());
  for (int i = 0; i < n; ++i) {
    const Evaluation& e = initial[i];
    f[i] = f_pbest[i] = e.fitness;
    feasible_pbest[i] = e.feasible;
    if (e.fitness < out.best_fitness || i == 0) {
      out.best_fitness = e.fitness;
      out.best_x = x[i];
      out.best_feasible = e.feasible;
    }
  }
  out.evaluations = n;

  Eigen::VectorXd b(dim), vb(dim), scratch(dim), mutant(dim);
  RunIterations(t_max, stop, observer, out, [&](const Iteration& iteration) {
    const int t = iteration.schedule_t;
    const double w = InertiaWeight(options.inertia, options.w_max, options.w_min, t, t_max);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      vb.setZero();
      if (options.antennae) {
        b = rng.UnitDirection(dim);
        const AntennaeProbe probe =
            ProbeAntennae(objective, x[i], b, delta / 2.0, scratch, options.positions);
        out.evaluations += 2;
        AddAntennaeStep(probe, b, delta, vb);
      }
      for (int j = 0; j < dim; ++j) {
        double vj = w * v[i][j] + options.c1 * rng.Uniform() * (pbest[i][j] - x[i][j]) +
                    options.c2 * rng.Uniform() * (out.best_x[j] - x[i][j]);
        if (options.antennae) vj += options.c3 * rng.Uniform() * vb[j];
        v[i][j] = std::clamp(vj, -v_max[j], v_max[j]);
      }
      x[i] += v[i];
      objective.Bound(options.positions, x[i]);
      const Evaluation e = objective.Evaluate(x[i]);
      ++out.evaluations;
      f[i] = e.fitness;
      sum += e.fitness;
      if (e.fitness < f_pbest[i]) {
        f_pbest[i] = e.fitness;
        pbest[i] = x[i];
        feasible_pbest[i] = e.feasible;
      }
      if (e.fitness < out.best_fitness) {
        out.best_fitness = e.fitness;
        out.best_x = x[i];
        out.best_feasible = e.feasible;
      }
    }
    const double mean = n > 0 ? sum / n : 0.0;
    if (options.elite_mutation) {
      options.mutation.Mutate(out.best_x, t, t_max, mean, out.best_fitness, rng, mutant);
      objective.Bound(options.positions, mutant);
      const Evaluation e = objective.Evaluate(mutant);
      ++out.evaluations;
      if (e.fitness < out.best_fitness) {
        out.best_fitness = e.fitness;
        out.best_x = mutant;
        out.best_feasible = e.feasible;
      }
    }
    delta *= options.step_decay;
    return IterationSummary{mean};
  });
  out.population = std::move(pbest);
  out.population_fitness = std::move(f_pbest);
  return out;
}

}  // namespace swarmplan
