#include "core/operators/objective.h"

#include <algorithm>

#include "core/random.h"

namespace swarmplan {

void Objective::SampleAroundStraightPath(double /*band*/, Rng& rng, Eigen::VectorXd& x) const {
  x.resize(dim());
  for (int j = 0; j < dim(); ++j) x[j] = rng.Uniform(lower()[j], upper()[j]);
}

void Objective::Bound(PositionBound bound, Eigen::VectorXd& x) const {
  if (bound == PositionBound::kBox) {
    Clamp(x);
    return;
  }
  // One expression, evaluated per coefficient: no temporary vector per move.
  x = x.cwiseMax(lower() - kFarBoxSpans * (upper() - lower()))
          .cwiseMin(upper() + kFarBoxSpans * (upper() - lower()));
}

void Objective::EvaluateColumns(const Eigen::MatrixXd& xs, Evaluation* out) {
  Eigen::VectorXd x(xs.rows());
  for (int j = 0; j < xs.cols(); ++j) {
    x = xs.col(j);
    out[j] = Evaluate(x);
  }
}

void PlaceInitialGuesses(const Objective& objective, Rng& rng,
                         std::vector<Eigen::VectorXd>& population) {
  const std::vector<Eigen::VectorXd> guesses = objective.InitialGuesses();
  const size_t count = std::min(guesses.size(), population.size());
  for (size_t i = 0; i < count; ++i) {
    population[i] = guesses[i].cwiseMax(objective.lower()).cwiseMin(objective.upper());
  }
  Eigen::VectorXd drawn;
  for (size_t i = count; i < population.size(); ++i) {
    if (objective.SampleNearGuesses(rng, drawn)) population[i] = drawn;
  }
}

}  // namespace swarmplan
