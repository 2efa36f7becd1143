#pragma once

// The Morris method of elementary effects (Morris 1991), the screening design the AS-BFO paper
// uses for its parameter sensitivity analysis: r trajectories over a p-level grid of the unit
// cube, each changing one factor at a time by ±Δ, and per factor the mean μ, the mean absolute
// value μ* and the standard deviation σ of its elementary effects.

#include <cstdint>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"

namespace swarmplan::bench {

// One trajectory: factors + 1 points of the grid {0, 1/(p−1), …, 1}^k; point i + 1 differs from
// point i in factor changed[i] alone, by ±Δ with Δ = p / (2 (p − 1)).
struct MorrisTrajectory {
  std::vector<std::vector<double>> points;
  std::vector<int> changed;
};

// `trajectories` trajectories of `factors` factors on a `levels`-level grid, drawn from `seed`:
// each factor starts at a uniformly drawn level and moves by Δ up (from the lower half of the
// levels) or down (from the upper half), the factors in a uniformly drawn order. INVALID_ARGUMENT
// unless factors ≥ 1, trajectories ≥ 1 and levels is even and ≥ 2.
absl::StatusOr<std::vector<MorrisTrajectory>> MorrisTrajectories(int factors, int levels,
                                                                 int trajectories, uint64_t seed);

// Δ of a `levels`-level grid.
double MorrisDelta(int levels);

struct MorrisIndices {
  // effects[f][t]: factor f's elementary effect on trajectory t, (y after − y before) divided
  // by the signed step of the factor.
  std::vector<std::vector<double>> effects;
  std::vector<double> mu;
  std::vector<double> mu_star;
  std::vector<double> sigma;  // sample standard deviation (divisor r − 1); 0 when r = 1
};

// The indices of one output: outputs[t][i] is the output at trajectories[t].points[i].
// INVALID_ARGUMENT when the shapes differ.
absl::StatusOr<MorrisIndices> MorrisElementaryEffects(
    const std::vector<MorrisTrajectory>& trajectories,
    const std::vector<std::vector<double>>& outputs);

// A percentile bootstrap interval of μ* (the mean of |effects|): `resamples` resamples of the
// trajectories' effects with replacement, from `seed`. nullopt when `effects` is empty.
struct MuStarInterval {
  double low = 0.0;
  double high = 0.0;
};
std::optional<MuStarInterval> BootstrapMuStar(const std::vector<double>& effects,
                                              double confidence = 0.95, int resamples = 10000,
                                              uint64_t seed = 1);

}  // namespace swarmplan::bench
