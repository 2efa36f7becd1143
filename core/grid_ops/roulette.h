#pragma once

#include <vector>

#include "core/random.h"

namespace swarmplan {

// Roulette-wheel selection: index i with probability weights[i] / sum(weights). Weights must be
// finite and >= 0; when they are all 0 the choice is uniform. -1 for an empty list.
int RouletteSelect(const std::vector<double>& weights, Rng& rng);

}  // namespace swarmplan
