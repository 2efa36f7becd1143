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
// [s, u1..uk, v1..vk] picks search space floor(s) (s in [0, E), one or two spaces per seed) and
// moves each of its k control points along its base by u_i (in [-1, 1], times half the distance
// to the nearer neighbouring control point) and across it by v_i (in [-1, 1], times the free
// extent of the corridor on that side, CorridorSection). The control points of a space are the
// interior vertices and the midpoints of the segments of its base polyline, in order (more
// midpoints on the longest gaps when another space has more, evenly thinned beyond
// `max_control_points`; a space whose corners are rounded has its own count, no midpoint inside
// a curve, and leaves the decision vector's other offsets unused). The moved points are the
// waypoints [x1..xk, y1..yk] of the space's FitnessEngine, which joins and evaluates them as for
// every waypoint planner:
// - with a turning radius, where the bounded-curvature smoothing of the seed is clear, the base
//   is the polygon whose corners the smoothing rounded (corner_polygon) and the engine rounds
//   the corners of the moved points in the same way (RoundedCornerPath): with every offset 0
//   the path is the smoothed seed, and a path that turns within the radius is one the smoothing
//   keeps as it is, so the swarm searches the paths the plan returns;
// - otherwise, and also where that smoothing has corners without room (whose seed then has both
//   spaces), the base is the seed and the engine's spline has a centripetal parameter (steps
//   the square root of the arc length between the control points along the seed), so it neither
//   overshoots between unevenly spaced control points nor loops where close ones move apart.
// With a turning radius, every space prices curvature above 1 / radius as a violation
// (curvature_as_violation): no plan may return such a turn. The spaces of one seed share its
// corridor (CorridorOf, KnownPathIn). The search space grows
// with the seeds' turns, not with the map.
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
  // Each space's base itself (selector at the middle of its interval, every offset 0), then
  // each with its control points moved toward the middle of their corridor sections by at most
  // a = max(preferred clearance, a field cell), a / 4 and a / 16 (a seed that grazes the walls
  // at the hard clearance has no feasible neighbour along most directions; these do), then each
  // spline space's seed after the bounded-curvature smoothing (its control points moved across
  // to where the smoothed path crosses their sections).
  std::vector<Eigen::VectorXd> InitialGuesses() const override { return guesses_; }
  // One of the initial guesses with each offset moved by up to a scale drawn log-uniformly from
  // 1/256 to 1 of its range: the rest of the population spread around the seeds, most of it in
  // the feasible neighbourhood of a seed that grazes the walls.
  bool SampleNearGuesses(Rng& rng, Eigen::VectorXd& x) const override;
  std::optional<KnownPath> BestKnownPath() override { return seed_paths_[best_seed_]; }
  int Corridors() const override { return seed_count_; }
  int CorridorOf(const Eigen::VectorXd& x) const override;
  int BestKnownCorridor() const override { return entry_seed_[best_seed_]; }
  std::optional<KnownPath> KnownPathIn(int corridor) override;

  int control_points() const { return k_; }
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
  // Adds to smoothed_guesses_ seed j smoothed to the turning radius, read at its sections.
  void FitSmoothedSeed(int j, const Path& smoothed);
  // What InitialGuesses returns, from the corridors and smoothed_guesses_.
  std::vector<Eigen::VectorXd> BuildGuesses() const;
  // The seed a selector s picks: floor(s), clamped to the seeds.
  int SeedIndex(double selector) const;

  int k_;
  // Per search space (entry; one or two per seed), its control points and its engine; the
  // selector s picks an entry.
  std::vector<std::vector<ControlPoint>> corridors_;
  std::vector<FitnessEngine> engines_;
  std::vector<int> entry_seed_;  // the seed (corridor) of each entry
  int seed_count_ = 0;
  // Each entry's seed and its fitness by the entry's engine: as the polyline it is or, where the
  // engine rounds the corners, as the smoothed seed (every offset 0).
  std::vector<KnownPath> seed_paths_;
  int best_seed_ = 0;  // the entry with the best seed fitness
  double away_ = 0.0;  // the largest move off the walls of the guesses (a)
  std::vector<Eigen::VectorXd> smoothed_guesses_;
  std::vector<Eigen::VectorXd> guesses_;  // BuildGuesses, once the objective is built
  Eigen::VectorXd lower_, upper_;
  Eigen::VectorXd single_;  // engine input, 2k
};

}  // namespace swarmplan
