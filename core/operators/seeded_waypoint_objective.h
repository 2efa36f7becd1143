#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "core/fitness/fitness_engine.h"
#include "core/geometry/collision.h"
#include "core/operators/objective.h"
#include "core/problem.h"
#include "core/seeds/corridor.h"
#include "core/seeds/seed_paths.h"

namespace swarmplan {

// The waypoint path problem on seed paths (FindSeedPaths): a decision vector
// [s, u1..uk, v1..vk] picks seed floor(s) (s in [0, K)) and moves each of its k control points
// along the seed by u_i (in [-1, 1], times half the distance to the nearer neighbouring control
// point) and across it by v_i (in [-1, 1], times the free extent of its corridor on that side,
// CorridorSection). The control points of a seed are its interior vertices and the midpoints of
// its segments, in order (more midpoints on the longest gaps when another seed has more, evenly
// thinned beyond `max_control_points`), so with every offset 0 the path is the seed itself
// under linear interpolation. The moved points are the waypoints [x1..xk, y1..yk] of the seed's
// FitnessEngine, which interpolates and evaluates them as for every waypoint planner; its spline
// has a centripetal parameter (steps the square root of the arc length between the control
// points along the seed), so it neither overshoots between unevenly spaced control points nor
// loops where close ones move apart. The search space grows with the seeds' turns, not with
// the map.
class SeededWaypointObjective final : public PathObjective {
 public:
  static absl::StatusOr<std::unique_ptr<SeededWaypointObjective>> Create(
      const Problem& problem, WaypointFitnessOptions options, const std::vector<SeedPath>& seeds,
      int max_control_points);

  int dim() const override { return 1 + 2 * k_; }
  const Eigen::VectorXd& lower() const override { return lower_; }
  const Eigen::VectorXd& upper() const override { return upper_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override;
  void EvaluateColumns(const Eigen::MatrixXd& xs, Evaluation* out) override;
  Path Decode(const Eigen::VectorXd& x) override;
  // The seeds themselves (selector at the middle of each seed's interval, every offset 0), then
  // each seed with its control points moved toward the middle of their corridor sections by at
  // most a = max(preferred clearance, a field cell), a / 4 and a / 16 (a seed that grazes the
  // walls at the hard clearance has no feasible neighbour along most directions; these do), then,
  // with a turning radius, each seed after the bounded-curvature smoothing (its control points
  // moved across to where the smoothed path crosses their sections).
  std::vector<Eigen::VectorXd> InitialGuesses() const override { return guesses_; }
  // One of the initial guesses with each offset moved by up to a scale drawn log-uniformly from
  // 1/256 to 1 of its range: the rest of the population spread around the seeds, most of it in
  // the feasible neighbourhood of a seed that grazes the walls.
  bool SampleNearGuesses(Rng& rng, Eigen::VectorXd& x) const override;
  std::optional<KnownPath> BestKnownPath() override { return seed_paths_[best_seed_]; }
  int Corridors() const override { return static_cast<int>(corridors_.size()); }
  int CorridorOf(const Eigen::VectorXd& x) const override;
  int BestKnownCorridor() const override { return best_seed_; }
  std::optional<KnownPath> KnownPathIn(int corridor) override { return seed_paths_[corridor]; }

  int control_points() const { return k_; }
  int seeds() const { return static_cast<int>(corridors_.size()); }
  // The engine that evaluates the paths of seed j's corridor.
  FitnessEngine& engine(int j) { return engines_[j]; }
  // The engine's waypoint vector [x1..xk, y1..yk] for a decision vector.
  void Waypoints(const double* x, double* waypoints) const;

 private:
  struct ControlPoint {
    CorridorSection section;
    Point2 tangent;
    double along = 0.0;  // the largest move along the seed
  };
  SeededWaypointObjective(int k, std::vector<std::vector<ControlPoint>> corridors,
                          std::vector<FitnessEngine> engines);
  // Fills smoothed_guesses_: each seed smoothed to the turning radius, read at the sections.
  void FitSmoothedSeeds(const std::vector<SeedPath>& seeds, double turning_radius, double clearance,
                        const CollisionChecker& checker);
  // What InitialGuesses returns, from the corridors and smoothed_guesses_.
  std::vector<Eigen::VectorXd> BuildGuesses() const;
  // The seed a selector s picks: floor(s), clamped to the seeds.
  int SeedIndex(double selector) const;

  int k_;
  std::vector<std::vector<ControlPoint>> corridors_;  // per seed, k control points
  std::vector<FitnessEngine> engines_;                // per seed
  std::vector<KnownPath> seed_paths_;  // each seed as a polyline, by the same fitness
  int best_seed_ = 0;
  double away_ = 0.0;  // the largest move off the walls of the guesses (a)
  std::vector<Eigen::VectorXd> smoothed_guesses_;
  std::vector<Eigen::VectorXd> guesses_;  // BuildGuesses, once the objective is built
  Eigen::VectorXd lower_, upper_;
  Eigen::VectorXd single_;  // engine input, 2k
};

}  // namespace swarmplan
