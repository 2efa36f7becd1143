#pragma once

#include <optional>
#include <vector>

namespace swarmplan::bench {

// Median of the values (the mean of the two middle ones for an even count); nullopt when empty.
std::optional<double> Median(std::vector<double> values);

// Largest value; nullopt when empty.
std::optional<double> Max(const std::vector<double>& values);

}  // namespace swarmplan::bench
