#include "core/operators/elite_mutation.h"

#include <algorithm>
#include <cmath>

#include "core/random.h"

namespace swarmplan {

double EliteMutation::Factor(int t, int t_max, double f_avg, double f_gbest, Rng& rng) const {
  const double g1 = t_max > 0 ? k1 * static_cast<double>(t) / t_max : k1;
  const double gap = std::isfinite(f_avg - f_gbest) ? f_avg - f_gbest : 0.0;
  const double g2 = k2 * std::exp(std::min(k3 * gap, 50.0));
  const double mu = rng.Uniform();
  const double s = g1 + g2 + mu;
  return rng.Bernoulli(0.5) ? 1.0 + s : 1.0 - s;
}

}  // namespace swarmplan
