#include "bench/significance.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "absl/strings/str_format.h"
#include "bench/statistics.h"
#include "core/random.h"

namespace swarmplan::bench {
namespace {

// The number of arrangements of m values of one sample and n of the other, without ties, whose
// U is u, for every u in [0, m n]: an arrangement ending in a value of the first sample adds n to
// U (it beats every value of the second), one ending in the second adds nothing.
std::vector<double> RankSumCounts(int m, int n) {
  // counts[i][j] for i values of the first sample, j of the second; the row i - 1 is kept.
  std::vector<std::vector<double>> previous(n + 1), current(n + 1);
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= n; ++j) {
      std::vector<double>& counts = current[j];
      counts.assign(static_cast<size_t>(i) * j + 1, 0.0);
      if (i == 0 || j == 0) {
        counts[0] = 1.0;
        continue;
      }
      const std::vector<double>& last_first = previous[j];  // i - 1, j: the last value is a's
      for (size_t u = 0; u < last_first.size(); ++u) counts[u + j] += last_first[u];
      const std::vector<double>& last_second = current[j - 1];  // i, j - 1: it is b's
      for (size_t u = 0; u < last_second.size(); ++u) counts[u] += last_second[u];
    }
    std::swap(previous, current);
  }
  return previous[n];
}

// The number of subsets of the ranks 1..n whose sum is v, for every v in [0, n (n + 1) / 2].
std::vector<double> SignedRankCounts(int n) {
  std::vector<double> counts(static_cast<size_t>(n) * (n + 1) / 2 + 1, 0.0);
  counts[0] = 1.0;
  for (int rank = 1, largest = 0; rank <= n; largest += rank, ++rank) {
    for (int v = largest; v >= 0; --v) counts[v + rank] += counts[v];
  }
  return counts;
}

// The two-sided exact p-value of an observed statistic from the number of arrangements giving
// each value of it (counts[k]: value k), out of `all`.
double TwoSidedExactP(const std::vector<double>& counts, double statistic, double all) {
  const size_t observed = static_cast<size_t>(std::lround(statistic));
  double at_most = 0.0, at_least = 0.0;
  for (size_t k = 0; k <= observed; ++k) at_most += counts[k];
  for (size_t k = observed; k < counts.size(); ++k) at_least += counts[k];
  return std::min(1.0, 2.0 * std::min(at_most, at_least) / all);
}

bool AllFinite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

double LogChoose(int n, int k) {
  return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
}

// The q-quantile of sorted values, interpolating linearly between order statistics.
double Quantile(const std::vector<double>& sorted, double q) {
  const double position = q * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - below) * (sorted[above] - sorted[below]);
}

}  // namespace

std::optional<RankSumTest> MannWhitneyU(const std::vector<double>& a,
                                        const std::vector<double>& b) {
  if (a.empty() || b.empty() || !AllFinite(a) || !AllFinite(b)) return std::nullopt;
  const int m = static_cast<int>(a.size()), n = static_cast<int>(b.size());
  const int total = m + n;
  // Midranks of the pooled values; the tie groups' sizes for the variance.
  std::vector<std::pair<double, int>> pooled;
  pooled.reserve(total);
  for (double v : a) pooled.emplace_back(v, 0);
  for (double v : b) pooled.emplace_back(v, 1);
  std::sort(pooled.begin(), pooled.end());
  double rank_sum_a = 0.0, tie_term = 0.0;
  bool ties = false;
  for (int i = 0; i < total;) {
    int j = i;
    while (j < total && pooled[j].first == pooled[i].first) ++j;
    const double midrank = 0.5 * (i + 1 + j);
    for (int k = i; k < j; ++k) {
      if (pooled[k].second == 0) rank_sum_a += midrank;
    }
    const double t = j - i;
    tie_term += t * t * t - t;
    ties = ties || t > 1;
    i = j;
  }
  RankSumTest result;
  result.u = rank_sum_a - 0.5 * m * (m + 1.0);
  const double mn = static_cast<double>(m) * n;
  if (!ties && total <= kExactRankSumValues) {
    const std::vector<double> counts = RankSumCounts(m, n);
    result.p_value =
        TwoSidedExactP(counts, result.u, std::accumulate(counts.begin(), counts.end(), 0.0));
    result.exact = true;
    return result;
  }
  const double variance = mn / 12.0 * ((total + 1.0) - tie_term / (total * (total - 1.0)));
  if (!(variance > 0.0)) return result;  // every value equal: no evidence of a difference
  const double deviation = std::abs(result.u - 0.5 * mn) - 0.5;
  const double z = std::max(0.0, deviation) / std::sqrt(variance);
  result.p_value = std::min(1.0, std::erfc(z / std::sqrt(2.0)));
  return result;
}

std::optional<SignedRankTest> WilcoxonSignedRank(const std::vector<double>& a,
                                                 const std::vector<double>& b) {
  if (a.empty() || a.size() != b.size() || !AllFinite(a) || !AllFinite(b)) return std::nullopt;
  std::vector<double> differences;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i] != b[i]) differences.push_back(a[i] - b[i]);
  }
  SignedRankTest result;
  const int n = static_cast<int>(differences.size());
  result.pairs = n;
  if (n == 0) return result;
  std::sort(differences.begin(), differences.end(),
            [](double x, double y) { return std::abs(x) < std::abs(y); });
  double tie_term = 0.0;
  bool ties = false;
  for (int i = 0; i < n;) {
    int j = i;
    while (j < n && std::abs(differences[j]) == std::abs(differences[i])) ++j;
    const double midrank = 0.5 * (i + 1 + j);
    for (int k = i; k < j; ++k) {
      if (differences[k] > 0) result.v += midrank;
    }
    const double t = j - i;
    tie_term += t * t * t - t;
    ties = ties || t > 1;
    i = j;
  }
  if (!ties && n <= kExactSignedRankPairs) {
    const std::vector<double> counts = SignedRankCounts(n);
    result.p_value = TwoSidedExactP(counts, result.v, std::ldexp(1.0, n));
    result.exact = true;
    return result;
  }
  const double mean = n * (n + 1.0) / 4.0;
  const double variance = n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - tie_term / 48.0;
  if (!(variance > 0.0)) return result;
  const double z = std::max(0.0, std::abs(result.v - mean) - 0.5) / std::sqrt(variance);
  result.p_value = std::min(1.0, std::erfc(z / std::sqrt(2.0)));
  return result;
}

std::optional<double> FisherExactTwoSided(int successes_a, int size_a, int successes_b,
                                          int size_b) {
  if (successes_a < 0 || successes_b < 0 || successes_a > size_a || successes_b > size_b) {
    return std::nullopt;
  }
  const int successes = successes_a + successes_b, total = size_a + size_b;
  // The hypergeometric probability of a table with x successes in the first sample.
  const double log_margins = LogChoose(total, successes);
  auto probability = [&](int x) {
    return std::exp(LogChoose(size_a, x) + LogChoose(size_b, successes - x) - log_margins);
  };
  const double observed = probability(successes_a);
  double p = 0.0;
  for (int x = std::max(0, successes - size_b); x <= std::min(successes, size_a); ++x) {
    const double px = probability(x);
    if (px <= observed * (1.0 + 1e-7)) p += px;
  }
  return std::min(1.0, p);
}

std::optional<Interval> BootstrapMedianInterval(const std::vector<double>& values,
                                                double confidence, int resamples, uint64_t seed) {
  if (values.empty() || !(confidence > 0.0 && confidence < 1.0) || resamples < 1) {
    return std::nullopt;
  }
  Rng rng(seed);
  const int64_t last = static_cast<int64_t>(values.size()) - 1;
  std::vector<double> resample(values.size()), medians(resamples);
  for (double& median : medians) {
    for (double& v : resample) v = values[rng.UniformInt(0, last)];
    median = *Median(resample);
  }
  std::sort(medians.begin(), medians.end());
  const double tail = 0.5 * (1.0 - confidence);
  return Interval{Quantile(medians, tail), Quantile(medians, 1.0 - tail)};
}

std::string FormatPValue(double p, bool mark_significant) {
  std::string text = p >= 1e-3 ? absl::StrFormat("p = %.3f", p) : absl::StrFormat("p = %.1e", p);
  if (mark_significant && p < kSignificanceLevel) text += " *";
  return text;
}

}  // namespace swarmplan::bench
