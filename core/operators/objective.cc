#include "core/operators/objective.h"

#include "core/random.h"

namespace swarmplan {

void Objective::SampleAroundStraightPath(double /*band*/, Rng& rng, Eigen::VectorXd& x) const {
  x.resize(dim());
  for (int j = 0; j < dim(); ++j) x[j] = rng.Uniform(lower()[j], upper()[j]);
}

}  // namespace swarmplan
