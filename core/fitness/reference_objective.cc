#include "core/fitness/reference_objective.h"

#include <algorithm>

namespace swarmplan {

absl::StatusOr<std::unique_ptr<ReferenceWaypointObjective>> ReferenceWaypointObjective::Create(
    const Problem& problem, const WaypointFitnessOptions& options) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("waypoint objective: no map");
  if (options.waypoints < 1) {
    return absl::InvalidArgumentError("waypoint objective: waypoints must be at least 1");
  }
  absl::StatusOr<ObstacleProximity> proximity =
      ObstacleProximity::Create(*problem.map, std::max(options.d_safe, problem.clearance));
  if (!proximity.ok()) return proximity.status();
  return std::unique_ptr<ReferenceWaypointObjective>(
      new ReferenceWaypointObjective(problem, options, *std::move(proximity)));
}

ReferenceWaypointObjective::ReferenceWaypointObjective(const Problem& problem,
                                                       const WaypointFitnessOptions& options,
                                                       ObstacleProximity proximity)
    : penalty_(options.penalty),
      builder_(problem.start, problem.goal, options.waypoints, options.interpolation,
               options.samples),
      proximity_(std::move(proximity)) {
  const int k = options.waypoints;
  lower_.resize(2 * k);
  upper_.resize(2 * k);
  lower_.head(k).setConstant(proximity_.lower().x());
  lower_.tail(k).setConstant(proximity_.lower().y());
  upper_.head(k).setConstant(proximity_.upper().x());
  upper_.tail(k).setConstant(proximity_.upper().y());
}

Evaluation ReferenceWaypointObjective::Evaluate(const Eigen::VectorXd& x) {
  const Path& path = builder_.Build(x);
  double length = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) length += (path[i + 1] - path[i]).norm();
  const int violations = proximity_.CountViolations(path);
  return {length * (1.0 + penalty_ * violations), violations == 0};
}

}  // namespace swarmplan
