#pragma once

#include <Eigen/Core>

namespace swarmplan {

class Rng;

// AEM-BSO's elite mutation (eqs 7-9): G1 = k1 t / t_max, G2 = k2 exp(k3 (f_avg - f_gbest)),
// gbest* = gbest * (1 +- (G1 + G2 + mu)), mu ~ U(0, 1), one sign for the whole vector with
// probability 1/2 each. The exponent is capped at 50 so that G2 stays finite.
struct EliteMutation {
  double k1 = 0.1;
  double k2 = 0.1;
  double k3 = -1.0;

  double Factor(int t, int t_max, double f_avg, double f_gbest, Rng& rng) const;
  void Mutate(const Eigen::VectorXd& gbest, int t, int t_max, double f_avg, double f_gbest,
              Rng& rng, Eigen::VectorXd& out) const {
    out = gbest * Factor(t, t_max, f_avg, f_gbest, rng);
  }
};

}  // namespace swarmplan
