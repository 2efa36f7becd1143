#pragma once

#include <Eigen/Core>
#include <optional>

#include "core/operators/objective.h"
#include "core/operators/search_loop.h"
#include "core/random.h"

namespace swarmplan {

// The beetle antennae search family of seed 000 as options of one loop.
//   BAS       population 1, direction random;
//   LFS-BAS   plus a local fast search of lfs_steps steps whenever a new best is found (eq 9-11);
//   SIO-BAS   population > 1, direction normalise(eta1 b1 + eta2 b2 + eta3 b3) (eq 16-18);
//   Multi-BAS the same population with eta2 = eta3 = 0.
// Each beetle: antennae at x +- d b, d = delta / c; x <- x + delta b toward the better antenna
// (clamped), then objective.Repair(theta, x) (the path rationality check on terrain), then
// evaluated; the best path is kept apart from the moving beetles. delta <- lambda1 delta and
// theta <- lambda2 theta per iteration. Optional PSO mix (eq 19): b <- m b + c1 (x_best - x)
// rand, renormalised. Beetles start from `seed` when given, else from the objective's initial
// guesses (a seeded objective's seeds, beetle j from guess j mod their number), else from the
// initial space C_ini: a band around the straight path widened by band_step after every
// infeasible draw.
// Ours, both off by default (the paper's loop):
//   relative_steps   step0 (so delta and d) is a fraction of each coordinate's range
//                    (upper - lower; the seeded terrain objective's box spans the map's extent
//                    in Y and its height range in Z): the beetle moves by delta (upper - lower)
//                    o b. The direction b, the vector to the best (eq 17) and the PSO term are
//                    taken in those units.
//   reject_infeasible a move (or a local fast search step) whose result is infeasible is
//                    undone: the beetle stays where it was.
struct BeetleAntennaeOptions {
  int population = 1;
  double step0 = 8.0;
  double step_decay = 0.998;
  double c = 2.0;
  double eta1 = 1.0;
  double eta2 = 0.0;
  double eta3 = 0.0;
  int lfs_steps = 0;
  double lfs_lambda = 0.95;
  double lfs_a = 1.0;
  double lfs_b = 1.0;
  double lfs_gamma = 1.0;
  double theta0 = 21.0;
  double theta_decay = 0.998;
  bool pso_mix = false;
  double pso_m = 1.0;
  double pso_c1 = 1.5;
  double band_step = 0.5;
  int max_initial_draws = 200;
  bool relative_steps = false;
  bool reject_infeasible = false;
};

SearchOutcome RunBeetleAntennae(Objective& objective, const BeetleAntennaeOptions& options,
                                int t_max, Rng& rng, const StopToken& stop, Observer& observer,
                                const std::optional<Eigen::VectorXd>& seed = std::nullopt);

}  // namespace swarmplan
