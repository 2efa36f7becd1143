#include "bench/papers/as_bfo_islands_extremes.h"

#include <algorithm>
#include <cmath>

#include "core/random.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

double ExtremeOf(std::vector<double>::const_iterator begin, std::vector<double>::const_iterator end,
                 Extreme extreme) {
  return extreme == Extreme::kMin ? *std::min_element(begin, end) : *std::max_element(begin, end);
}

}  // namespace

std::optional<double> ExtremePermutationP(const std::vector<double>& a,
                                          const std::vector<double>& b, Extreme extreme,
                                          int permutations, uint64_t seed) {
  if (a.empty() || b.empty() || permutations < 1) return std::nullopt;
  std::vector<double> pooled = a;
  pooled.insert(pooled.end(), b.begin(), b.end());
  const auto split = pooled.begin() + static_cast<std::ptrdiff_t>(a.size());
  const double observed =
      std::abs(ExtremeOf(a.begin(), a.end(), extreme) - ExtremeOf(b.begin(), b.end(), extreme));
  // Differences that equal the observed one up to rounding count as at least as large.
  const double tolerance = 1e-9 * std::max(1.0, observed);
  Rng rng(seed);
  int at_least = 0;
  for (int k = 0; k < permutations; ++k) {
    // A uniformly random split: the first a.size() places of a partial Fisher-Yates shuffle.
    for (size_t i = 0; i < a.size(); ++i) {
      const size_t j = static_cast<size_t>(
          rng.UniformInt(static_cast<int64_t>(i), static_cast<int64_t>(pooled.size()) - 1));
      std::swap(pooled[i], pooled[j]);
    }
    const double difference = std::abs(ExtremeOf(pooled.begin(), split, extreme) -
                                       ExtremeOf(split, pooled.end(), extreme));
    if (difference >= observed - tolerance) ++at_least;
  }
  return (1.0 + at_least) / (1.0 + permutations);
}

}  // namespace swarmplan::bench::as_bfo_islands
