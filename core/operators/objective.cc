#include "core/operators/objective.h"

#include "core/random.h"

namespace swarmplan {

void Objective::SampleAroundStraightPath(double /*band*/, Rng& rng, Eigen::VectorXd& x) const {
  x.resize(dim());
  for (int j = 0; j < dim(); ++j) x[j] = rng.Uniform(lower()[j], upper()[j]);
}

void Objective::EvaluateColumns(const Eigen::MatrixXd& xs, Evaluation* out) {
  Eigen::VectorXd x(xs.rows());
  for (int j = 0; j < xs.cols(); ++j) {
    x = xs.col(j);
    out[j] = Evaluate(x);
  }
}

}  // namespace swarmplan
