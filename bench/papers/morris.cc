#include "bench/papers/morris.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "absl/strings/str_cat.h"
#include "core/random.h"

namespace swarmplan::bench {

double MorrisDelta(int levels) { return levels / (2.0 * (levels - 1)); }

absl::StatusOr<std::vector<MorrisTrajectory>> MorrisTrajectories(int factors, int levels,
                                                                 int trajectories, uint64_t seed) {
  if (factors < 1 || trajectories < 1 || levels < 2 || levels % 2 != 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("Morris design needs factors >= 1 (", factors, "), trajectories >= 1 (",
                     trajectories, ") and an even number of levels (", levels, ")"));
  }
  const int jump = levels / 2;  // Δ in grid steps
  const double step = 1.0 / (levels - 1);
  Rng rng(seed);
  std::vector<MorrisTrajectory> out;
  out.reserve(trajectories);
  for (int t = 0; t < trajectories; ++t) {
    std::vector<int> level(factors);
    for (int& l : level) l = static_cast<int>(rng.UniformInt(0, levels - 1));
    std::vector<int> order(factors);
    std::iota(order.begin(), order.end(), 0);
    for (int i = factors - 1; i > 0; --i) {
      std::swap(order[i], order[static_cast<size_t>(rng.UniformInt(0, i))]);
    }
    MorrisTrajectory trajectory;
    auto point = [&] {
      std::vector<double> x(factors);
      for (int f = 0; f < factors; ++f) x[f] = level[f] * step;
      return x;
    };
    trajectory.points.push_back(point());
    for (int f : order) {
      level[f] += level[f] < jump ? jump : -jump;
      trajectory.points.push_back(point());
      trajectory.changed.push_back(f);
    }
    out.push_back(std::move(trajectory));
  }
  return out;
}

absl::StatusOr<MorrisIndices> MorrisElementaryEffects(
    const std::vector<MorrisTrajectory>& trajectories,
    const std::vector<std::vector<double>>& outputs) {
  if (trajectories.empty() || outputs.size() != trajectories.size()) {
    return absl::InvalidArgumentError("one output row per trajectory is needed");
  }
  const size_t factors = trajectories.front().changed.size();
  MorrisIndices indices;
  indices.effects.assign(factors, {});
  for (size_t t = 0; t < trajectories.size(); ++t) {
    const MorrisTrajectory& trajectory = trajectories[t];
    if (trajectory.changed.size() != factors || trajectory.points.size() != factors + 1 ||
        outputs[t].size() != factors + 1) {
      return absl::InvalidArgumentError(
          absl::StrCat("trajectory ", t, ": points, changed factors and outputs disagree"));
    }
    for (size_t i = 0; i < factors; ++i) {
      const size_t f = static_cast<size_t>(trajectory.changed[i]);
      if (f >= factors) return absl::InvalidArgumentError("changed factor out of range");
      const double step = trajectory.points[i + 1][f] - trajectory.points[i][f];
      indices.effects[f].push_back((outputs[t][i + 1] - outputs[t][i]) / step);
    }
  }
  for (const std::vector<double>& e : indices.effects) {
    const double r = static_cast<double>(e.size());
    double sum = 0.0, sum_abs = 0.0;
    for (double v : e) {
      sum += v;
      sum_abs += std::abs(v);
    }
    const double mu = sum / r;
    double squares = 0.0;
    for (double v : e) squares += (v - mu) * (v - mu);
    indices.mu.push_back(mu);
    indices.mu_star.push_back(sum_abs / r);
    indices.sigma.push_back(e.size() > 1 ? std::sqrt(squares / (r - 1.0)) : 0.0);
  }
  return indices;
}

std::optional<MuStarInterval> BootstrapMuStar(const std::vector<double>& effects, double confidence,
                                              int resamples, uint64_t seed) {
  if (effects.empty() || resamples < 1 || !(confidence > 0.0 && confidence < 1.0)) {
    return std::nullopt;
  }
  Rng rng(seed);
  const int64_t n = static_cast<int64_t>(effects.size());
  std::vector<double> means;
  means.reserve(resamples);
  for (int b = 0; b < resamples; ++b) {
    double sum = 0.0;
    for (int64_t i = 0; i < n; ++i) sum += std::abs(effects[rng.UniformInt(0, n - 1)]);
    means.push_back(sum / n);
  }
  std::sort(means.begin(), means.end());
  const double tail = (1.0 - confidence) / 2.0;
  auto at = [&](double q) {
    const size_t i = static_cast<size_t>(
        std::clamp(std::floor(q * (resamples - 1) + 0.5), 0.0, static_cast<double>(resamples - 1)));
    return means[i];
  };
  return MuStarInterval{at(tail), at(1.0 - tail)};
}

}  // namespace swarmplan::bench
