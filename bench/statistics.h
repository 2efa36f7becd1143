#pragma once

#include <optional>
#include <vector>

namespace swarmplan::bench {

// Median of the values (the mean of the two middle ones for an even count); nullopt when empty.
std::optional<double> Median(std::vector<double> values);

// Largest value; nullopt when empty.
std::optional<double> Max(const std::vector<double>& values);

// Smallest value; nullopt when empty.
std::optional<double> Min(const std::vector<double>& values);

// Arithmetic mean; nullopt when empty.
std::optional<double> Mean(const std::vector<double>& values);

// Sample standard deviation (divisor n - 1); 0 for one value, nullopt when empty.
std::optional<double> StdDev(const std::vector<double>& values);

}  // namespace swarmplan::bench
