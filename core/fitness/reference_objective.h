#pragma once

#include <memory>

#include "absl/status/statusor.h"
#include "core/fitness/fitness_engine.h"
#include "core/operators/objective.h"
#include "core/operators/waypoint_path.h"

namespace swarmplan {

// The papers' waypoint fitness z = L (1 + M xi) computed the direct way, one path at a time:
// the spline fitted by WaypointPathBuilder (a tridiagonal solve per evaluation) and xi by
// ObstacleProximity's unscreened count. The yardstick the FitnessEngine is tested and measured
// against; no planner uses it.
class ReferenceWaypointObjective final : public PathObjective {
 public:
  static absl::StatusOr<std::unique_ptr<ReferenceWaypointObjective>> Create(
      const Problem& problem, const WaypointFitnessOptions& options);

  int dim() const override { return 2 * builder_.waypoints(); }
  const Eigen::VectorXd& lower() const override { return lower_; }
  const Eigen::VectorXd& upper() const override { return upper_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override;
  Path Decode(const Eigen::VectorXd& x) override { return builder_.Build(x); }

 private:
  ReferenceWaypointObjective(const Problem& problem, const WaypointFitnessOptions& options,
                             ObstacleProximity proximity);

  double penalty_;
  WaypointPathBuilder builder_;
  ObstacleProximity proximity_;
  Eigen::VectorXd lower_, upper_;
};

}  // namespace swarmplan
