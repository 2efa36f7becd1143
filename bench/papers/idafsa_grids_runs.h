#pragma once

// The runs of the IDAFSA reproduction: one planner configuration on one world, many seeds, with
// every found path checked and its Bezier smoothing measured.

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "bench/papers/experiment.h"
#include "bench/papers/idafsa_grids_worlds.h"
#include "core/map/map.h"
#include "core/params.h"
#include "core/run.h"

namespace swarmplan::bench {

// A planner configuration: the registered planner and the parameters that differ from its
// defaults (population, try_number, visual, δ and MAXGEN are set by the run itself).
struct FishConfig {
  std::string label;
  std::string algorithm;
  ParamValues params;
};

// What the runs of one configuration on one world gave. Lengths and the rest are over the
// successful runs (a collision-free path from start to goal) unless said otherwise.
struct FishRunStats {
  int runs = 0;
  int cut_corner = 0;  // arrivals whose path touched a blocked corner or edge only
  int jumped = 0;      // arrivals whose path went through the inside of a blocked cell
  std::vector<double> lengths, turning_points, best_iterations;
  std::vector<double> all_arrival_lengths;  // including the cut_corner and jumped ones
  std::vector<double> millis, iterations;   // every run
  // Bezier smoothing of the successful paths.
  std::vector<double> kappa, sampled_kappa, smoothed_lengths;
  int corners = 0, corners_limited = 0, corners_shrunk = 0, corners_sharp = 0;
  int kappa_within_bound = 0, smoothed_free = 0;

  int successes() const { return static_cast<int>(lengths.size()); }
  int no_path() const { return runs - successes() - cut_corner - jumped; }
};

// The paper's settings for every fish planner: N = 50, try_number = 8, visual 5, δ = 0.618, and
// m = 17 on 10 x 10, 10 on 20 x 20 for idafsa; the config's params override them.
ParamValues PaperFishParams(const FishConfig& config, const IdafsaGridWorld& world,
                            int max_generations);

// Runs the configuration with seeds options.seed ... options.seed + runs - 1 and smoothing
// "bezier". INTERNAL error when a found path is not collision-free or does not run from start to
// goal.
absl::StatusOr<FishRunStats> RunFishConfig(const FishConfig& config, const IdafsaGridWorld& world,
                                           const MapPtr& map, const ExperimentOptions& options,
                                           int runs, int max_generations);

// A deterministic reference planner (astar, theta-star) run once; an error when it finds no
// valid path.
absl::StatusOr<PlanResult> RunReference(const std::string& algorithm, const IdafsaGridWorld& world,
                                        const MapPtr& map);

// The world's grid as shipped under options.worlds_dir.
absl::StatusOr<MapPtr> LoadIdafsaWorld(const ExperimentOptions& options,
                                       const IdafsaGridWorld& world);

}  // namespace swarmplan::bench
