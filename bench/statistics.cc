#include "bench/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace swarmplan::bench {

std::optional<double> Median(std::vector<double> values) {
  if (values.empty()) return std::nullopt;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(), values.begin() + mid);
  return lower + (upper - lower) / 2;
}

std::optional<double> Max(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  return *std::max_element(values.begin(), values.end());
}

std::optional<double> Min(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  return *std::min_element(values.begin(), values.end());
}

std::optional<double> Mean(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

std::optional<double> StdDev(const std::vector<double>& values) {
  const std::optional<double> mean = Mean(values);
  if (!mean) return std::nullopt;
  if (values.size() == 1) return 0.0;
  double sum_of_squares = 0.0;
  for (double value : values) sum_of_squares += (value - *mean) * (value - *mean);
  return std::sqrt(sum_of_squares / static_cast<double>(values.size() - 1));
}

}  // namespace swarmplan::bench
