#pragma once

// The AS-BFO paper's Table 4 (Long et al.), as printed: [environment][method][size S1..S5].

namespace swarmplan::bench::as_bfo_paper {

inline constexpr int kEnvironments = 2;
inline constexpr int kMethods = 3;  // AS-BFO, ACO, GA
inline constexpr int kSizes = 5;

using Table = double[kEnvironments][kMethods][kSizes];

// Average iteration number.
inline constexpr Table kAin = {
    {{1.2, 1.3, 2.3, 2.8, 2.8}, {6.3, 9.2, 11.9, 8.0, 7.8}, {21.4, 48.6, 76.9, 85.7, 88.3}},
    {{1.0, 1.8, 4.6, 3.4, 3.6}, {3.8, 14.8, 25.7, 8.7, 9.3}, {13.0, 56.0, 74.3, 82.5, 91.3}},
};
// Maximum path length over 20 runs.
inline constexpr Table kMaxLength = {
    {{13.90, 21.56, 30.39, 40.38, 50.87},
     {13.90, 22.97, 33.80, 64.77, 127.54},
     {13.90, 22.73, 32.97, 47.21, 68.53}},
    {{14.49, 22.73, 31.21, 41.80, 48.87},
     {14.49, 22.97, 32.04, 73.84, 101.88},
     {15.07, 23.56, 34.39, 46.87, 60.87}},
};
// Minimum path length over 20 runs.
inline constexpr Table kMinLength = {
    {{13.31, 20.97, 28.62, 35.11, 45.11},
     {13.31, 20.97, 29.21, 41.11, 85.50},
     {13.31, 20.97, 29.21, 36.87, 48.87}},
    {{14.49, 21.56, 28.62, 39.21, 43.95},
     {14.49, 21.56, 29.21, 53.70, 101.88},
     {14.49, 21.56, 30.04, 39.80, 46.53}},
};
// Average path length over 20 runs.
inline constexpr Table kMeanLength = {
    {{13.37, 21.18, 29.57, 38.94, 48.46},
     {13.40, 21.46, 29.95, 55.13, 101.65},
     {13.61, 21.73, 30.46, 41.54, 68.53}},
    {{14.49, 21.89, 30.18, 40.14, 46.94},
     {14.49, 22.14, 30.89, 64.30, 89.43},
     {14.51, 22.72, 30.95, 42.66, 52.93}},
};

}  // namespace swarmplan::bench::as_bfo_paper
