#include "core/operators/waypoint_objective.h"

#include <algorithm>

#include "core/random.h"

namespace swarmplan {

absl::StatusOr<std::unique_ptr<WaypointObjective>> WaypointObjective::Create(
    const Problem& problem, const WaypointFitnessOptions& options) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("waypoint objective: no map");
  if (options.waypoints < 1) {
    return absl::InvalidArgumentError("waypoint objective: waypoints must be at least 1");
  }
  absl::StatusOr<ObstacleProximity> proximity =
      ObstacleProximity::Create(*problem.map, std::max(options.d_safe, problem.clearance));
  if (!proximity.ok()) return proximity.status();
  return std::unique_ptr<WaypointObjective>(
      new WaypointObjective(problem, options, *std::move(proximity)));
}

WaypointObjective::WaypointObjective(const Problem& problem, const WaypointFitnessOptions& options,
                                     ObstacleProximity proximity)
    : start_(problem.start.head<2>()),
      goal_(problem.goal.head<2>()),
      penalty_(options.penalty),
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

Evaluation WaypointObjective::Evaluate(const Eigen::VectorXd& x) {
  const Path& path = builder_.Build(x);
  double length = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) length += (path[i + 1] - path[i]).norm();
  const int violations = proximity_.CountViolations(path);
  return {length * (1.0 + penalty_ * violations), violations == 0};
}

void WaypointObjective::SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& x) const {
  const int k = builder_.waypoints();
  x.resize(2 * k);
  const Point2 along = goal_ - start_;
  const double length = along.norm();
  const Point2 unit = length > 0 ? Point2(along / length) : Point2(1.0, 0.0);
  const Point2 normal(-unit.y(), unit.x());
  for (int i = 0; i < k; ++i) {
    const Point2 base = start_ + along * (static_cast<double>(i + 1) / (k + 1));
    const double u = rng.Uniform(-band, band);
    const double v = rng.Uniform(-band, band);
    const Point2 p = base + u * unit + v * normal;
    x[i] = p.x();
    x[k + i] = p.y();
  }
  Clamp(x);
}

}  // namespace swarmplan
