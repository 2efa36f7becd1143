#include "core/operators/good_point_set.h"

#include <cmath>
#include <numbers>

namespace swarmplan {

int SmallestPrimeAtLeast(int n) {
  for (int p = std::max(n, 2);; ++p) {
    bool prime = true;
    for (int d = 2; d * d <= p; ++d) {
      if (p % d == 0) {
        prime = false;
        break;
      }
    }
    if (prime) return p;
  }
}

std::vector<Eigen::VectorXd> GoodPointSet(int count, const Eigen::VectorXd& lower,
                                          const Eigen::VectorXd& upper) {
  const int dim = static_cast<int>(lower.size());
  const int p = SmallestPrimeAtLeast(2 * dim + 3);
  Eigen::VectorXd r(dim);
  for (int j = 0; j < dim; ++j) r[j] = 2.0 * std::cos(2.0 * std::numbers::pi * (j + 1) / p);
  std::vector<Eigen::VectorXd> points;
  points.reserve(count);
  for (int k = 1; k <= count; ++k) {
    Eigen::VectorXd x(dim);
    for (int j = 0; j < dim; ++j) {
      const double v = k * r[j];
      x[j] = lower[j] + (upper[j] - lower[j]) * (v - std::floor(v));
    }
    points.push_back(std::move(x));
  }
  return points;
}

}  // namespace swarmplan
