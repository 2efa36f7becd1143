#pragma once

// The AEM-BSO paper's Table 1 (seed 002): the best and mean final value of each optimiser on
// f1-f10 over 100 runs (population 100, 1000 iterations), at D = 30 and D = 60.

#include <array>

namespace swarmplan::bench::aem_bso {

struct Algorithm {
  const char* planner_id;
  const char* paper_name;
};

// Table 1's column order.
inline constexpr std::array<Algorithm, 5> kAlgorithms = {{{"aem-bso", "AEM-BSO"},
                                                          {"aem-bso-linear", "AEM-BSO2"},
                                                          {"bso", "BSO"},
                                                          {"pso", "PSO"},
                                                          {"ba", "BA"}}};

// One function's row pair of Table 1 at one dimension, in kAlgorithms' order.
struct PaperRow {
  std::array<double, 5> best;
  std::array<double, 5> mean;
};

// Table 1, D = 30 (100 runs, population 100, 1000 iterations), f1..f10.
inline constexpr std::array<PaperRow, 10> kPaperD30 = {{
    {{2.68e-174, 4.91e-159, 6.76e-2, 3.15e0, 3.44e0},
     {1.98e-154, 1.99e-143, 4.82e0, 3.09e1, 5.03e0}},
    {{0, 0, 4.00e1, 5.20e1, 4.00e0}, {2.00e-2, 2.50e-1, 1.48e2, 1.94e2, 6.94e0}},
    {{2.91e-5, 1.07e-2, 9.54e1, 3.65e2, 5.22e2}, {1.29e-1, 3.66e-1, 5.97e2, 3.96e3, 1.57e3}},
    {{4.23e-170, 4.69e-157, 2.79e1, 1.36e2, 9.15e0},
     {2.00e-154, 2.32e-143, 1.67e2, 3.60e2, 1.54e1}},
    {{1.26e-179, 1.69e-166, 2.43e-3, 5.01e-2, 3.61e0},
     {3.52e-157, 1.88e-148, 7.29e-2, 4.30e-1, 1.60e2}},
    {{1.26e-163, 2.67e-156, 6.03e4, 1.20e5, 5.47e5},
     {7.38e-149, 2.48e-139, 2.74e5, 7.58e5, 2.57e6}},
    {{1.69e1, 3.08e1, 2.11e1, 2.23e1, 2.02e2}, {5.12e1, 6.12e1, 5.38e1, 5.26e1, 2.50e2}},
    {{0, 2.08e-1, 2.89e-1, 8.60e-1, 2.03e-1}, {1.77e-3, 2.66e-1, 9.35e-1, 1.27e0, 2.68e-1}},
    {{-4.44e-16, -4.44e-16, 2.53e0, 3.11e0, 3.01e0}, {2.58e-15, 2.58e-15, 5.66e0, 5.48e0, 5.19e0}},
    {{0, 0, 1.74e1, 2.70e1, 2.81e1}, {0, 1.10e-1, 4.03e1, 6.25e1, 3.39e1}},
}};

// Table 1, D = 60.
inline constexpr std::array<PaperRow, 10> kPaperD60 = {{
    {{1.94e-171, 9.95e-163, 2.00e2, 3.71e2, 1.53e1},
     {2.45e-156, 1.32e-145, 4.81e2, 8.32e2, 2.23e1}},
    {{0, 0, 6.20e2, 7.61e2, 2.30e1}, {0, 0, 1.11e3, 1.40e3, 3.30e1}},
    {{4.76e1, 4.81e1, 8.22e3, 3.92e4, 3.27e3}, {4.94e1, 4.96e1, 1.01e5, 2.09e5, 6.15e3}},
    {{2.08e-170, 1.81e-163, 6.01e2, 1.25e3, 2.19e2},
     {1.91e-152, 5.90e-142, 1.70e3, 2.57e3, 3.73e2}},
    {{1.52e-173, 1.52e-163, 1.84e0, 4.33e0, 1.98e1},
     {7.34e-132, 6.93e-127, 5.90e0, 9.55e0, 6.38e16}},
    {{1.98e-164, 1.01e-152, 1.07e6, 1.63e6, 4.30e6},
     {1.96e-149, 1.60e-140, 3.30e6, 6.68e6, 8.82e6}},
    {{3.48e1, 4.78e1, 1.13e2, 1.30e2, 5.35e2}, {1.08e2, 1.12e2, 1.68e2, 1.97e2, 6.39e2}},
    {{0, 0, 2.84e0, 3.63e0, 4.62e-1}, {1.75e-3, 2.44e-3, 5.19e0, 8.13e0, 5.60e-1}},
    {{-4.44e-16, -4.44e-16, 5.88e0, 6.03e0, 3.91e0}, {2.43e-15, 2.72e-15, 7.44e0, 7.54e0, 8.29e0}},
    {{0, 0, 1.81e2, 3.59e2, 9.06e1}, {0, 0, 4.57e2, 7.10e2, 1.08e2}},
}};

}  // namespace swarmplan::bench::aem_bso
