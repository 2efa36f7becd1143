#pragma once

#include <memory>

#include "absl/status/statusor.h"
#include "core/fitness/fitness_engine.h"
#include "core/operators/objective.h"
#include "core/problem.h"

namespace swarmplan {

// The 2D waypoint path problem of AEM-BSO: decision vector [x1..xk, y1..yk] inside the map's
// rectangle shrunk by `box_inset` on each side, path as WaypointPathBuilder builds it, fitness z =
// L (1 + M xi) with L the path's length and xi the number of obstacles it comes closer to than
// max(d_safe, clearance) (eq 21), or the fleet objective when the options carry one. Feasible means
// xi = 0. Evaluated by the FitnessEngine: no allocation per evaluation.
class WaypointObjective final : public PathObjective {
 public:
  static absl::StatusOr<std::unique_ptr<WaypointObjective>> Create(
      const Problem& problem, const WaypointFitnessOptions& options, double box_inset = 0.0);

  int dim() const override { return 2 * waypoints_; }
  const Eigen::VectorXd& lower() const override { return lower_; }
  const Eigen::VectorXd& upper() const override { return upper_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override { return engine_.Evaluate(x); }
  void EvaluateColumns(const Eigen::MatrixXd& xs, Evaluation* out) override {
    engine_.Evaluate(xs, out);
  }
  Path Decode(const Eigen::VectorXd& x) override;
  FitnessEngine& engine() { return engine_; }
  // Waypoints spread evenly along the start-goal segment, each moved by up to `band` along and
  // across it, clamped to the map.
  void SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& x) const override;

 private:
  WaypointObjective(const Problem& problem, int waypoints, double box_inset, FitnessEngine engine);

  Point2 start_, goal_;
  int waypoints_;
  FitnessEngine engine_;
  Eigen::VectorXd lower_, upper_;
};

}  // namespace swarmplan
