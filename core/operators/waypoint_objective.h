#pragma once

#include <memory>

#include "absl/status/statusor.h"
#include "core/operators/objective.h"
#include "core/operators/obstacle_proximity.h"
#include "core/operators/waypoint_path.h"
#include "core/problem.h"

namespace swarmplan {

struct WaypointFitnessOptions {
  int waypoints = 3;
  Interpolation interpolation = Interpolation::kSpline;
  int samples = 100;     // spline sample count
  double penalty = 100;  // M
  double d_safe = 1.5;   // the safety distance; the problem's clearance when larger
};

// The 2D waypoint path problem of AEM-BSO: decision vector [x1..xk, y1..yk] inside the map's
// rectangle, path built by WaypointPathBuilder, fitness z = L (1 + M xi) with L the path's
// length and xi the number of obstacles it comes closer to than max(d_safe, clearance) (eq 21).
// Feasible means xi = 0. No allocation per evaluation.
class WaypointObjective final : public PathObjective {
 public:
  static absl::StatusOr<std::unique_ptr<WaypointObjective>> Create(
      const Problem& problem, const WaypointFitnessOptions& options);

  int dim() const override { return 2 * builder_.waypoints(); }
  const Eigen::VectorXd& lower() const override { return lower_; }
  const Eigen::VectorXd& upper() const override { return upper_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override;
  Path Decode(const Eigen::VectorXd& x) override { return builder_.Build(x); }
  // Waypoints spread evenly along the start-goal segment, each moved by up to `band` along and
  // across it, clamped to the map.
  void SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& x) const override;

 private:
  WaypointObjective(const Problem& problem, const WaypointFitnessOptions& options,
                    ObstacleProximity proximity);

  Point2 start_, goal_;
  double penalty_;
  WaypointPathBuilder builder_;
  ObstacleProximity proximity_;
  Eigen::VectorXd lower_, upper_;
};

}  // namespace swarmplan
