#include "core/grid_ops/roulette.h"

namespace swarmplan {

int RouletteSelect(const std::vector<double>& weights, Rng& rng) {
  if (weights.empty()) return -1;
  double total = 0.0;
  for (double w : weights) total += w;
  if (!(total > 0.0)) {
    return static_cast<int>(rng.UniformInt(0, static_cast<int64_t>(weights.size()) - 1));
  }
  const double r = rng.Uniform() * total;
  double acc = 0.0;
  int last_positive = 0;
  for (size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] <= 0.0) continue;
    acc += weights[i];
    last_positive = static_cast<int>(i);
    if (r < acc) return static_cast<int>(i);
  }
  return last_positive;  // rounding at the top end
}

}  // namespace swarmplan
