#pragma once

// The runs of the AEM-BSO path-planning reproduction: one planner configuration on one world,
// many seeds, every found path checked, as the paper's Tables 2-3 run them.

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/comparison.h"
#include "bench/papers/experiment.h"
#include "bench/papers/plan_once.h"
#include "core/map/map.h"

namespace swarmplan::bench::aem_bso {

inline constexpr int kPopulation = 100;
inline constexpr double kPenalty = 100.0;     // M of z = L (1 + M xi)
inline constexpr double kPaperFactor = 1.49;  // c1 = c2 (= c3) of every swarm in the paper

// What the runs of one planner x interpolation on one world gave.
struct CellStats {
  int runs = 0;
  std::vector<double> lengths;    // of the runs that found a path (xi = 0)
  std::vector<double> fitnesses;  // z = L (1 + M xi) of every run
  std::vector<double> seconds;    // wall time of every run
  std::vector<double> cpu_seconds;
  std::vector<double> best_iterations;
  std::vector<double> evaluations;               // fitness evaluations of every run
  std::vector<std::vector<double>> convergence;  // [run][iteration]: best z so far

  int found() const { return static_cast<int>(lengths.size()); }
  SuccessCount Found() const { return {found(), runs}; }
};

// The paper's run of `planner` with `interpolation` (its factors for PSO).
PlanSpec PaperPlan(const std::string& planner, const std::string& interpolation, int iterations);

// `runs` runs of `plan` with seeds options.seed, options.seed + 1, ..., every found path
// checked; progress goes to options.log, labelled `what`.
absl::StatusOr<CellStats> RunCell(const PlanSpec& plan, const MapPtr& map,
                                  const ExperimentOptions& options, int runs,
                                  const std::string& what);

// The exact shortest path keeping d_safe from start to goal (visibility-graph), its length
// checked; FAILED_PRECONDITION when there is none.
absl::StatusOr<double> ExactOptimum(const MapPtr& map, uint64_t seed, const std::string& what);

}  // namespace swarmplan::bench::aem_bso
