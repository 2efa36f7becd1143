#pragma once

#include <cstdint>
#include <random>

#include "core/map/point.h"

namespace swarmplan {

// The one random engine of a job. The engine is std::mt19937_64, whose output sequence the C++
// standard fixes; every draw is converted by our own code (never std::*_distribution, whose
// results differ between standard libraries), so a seed reproduces a path bit for bit.
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  uint64_t NextU64() { return engine_(); }
  // Uniform in [0, 1), 53 random bits.
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  // Uniform integer in [lo, hi] (inclusive), without modulo bias.
  int64_t UniformInt(int64_t lo, int64_t hi);
  bool Bernoulli(double p) { return Uniform() < p; }
  // Standard normal (Marsaglia polar method).
  double Normal();
  double Normal(double mean, double stddev) { return mean + stddev * Normal(); }

  // A unit vector uniformly distributed on the sphere of dimension `dim` (normalised normals).
  Eigen::VectorXd UnitDirection(int dim);

 private:
  std::mt19937_64 engine_;
  bool has_spare_normal_ = false;
  double spare_normal_ = 0.0;
};

// A seed for a request that asked for "any" (0): drawn from the system's entropy, never 0.
uint64_t PickSeed();

}  // namespace swarmplan
