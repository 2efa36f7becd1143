#pragma once

#include <Eigen/Core>
#include <vector>

namespace swarmplan {

// The smallest prime >= n (n >= 2).
int SmallestPrimeAtLeast(int n);

// The good point set of AEM-BSO eq 5: p the smallest prime >= 2D + 3, r_j = 2 cos(2 pi j / p)
// (j = 1..D), point k (k = 1..count) = lb + (ub - lb) * frac(k r_j), frac(x) = x - floor(x).
std::vector<Eigen::VectorXd> GoodPointSet(int count, const Eigen::VectorXd& lower,
                                          const Eigen::VectorXd& upper);

}  // namespace swarmplan
