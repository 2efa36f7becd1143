#include "core/operators/waypoint_objective.h"

#include <algorithm>

#include "absl/strings/str_format.h"
#include "core/random.h"

namespace swarmplan {

absl::StatusOr<std::unique_ptr<WaypointObjective>> WaypointObjective::Create(
    const Problem& problem, const WaypointFitnessOptions& options, double box_inset) {
  absl::StatusOr<FitnessEngine> engine = FitnessEngine::Create(problem, options);
  if (!engine.ok()) return engine.status();
  const Point2 size = engine->proximity().upper() - engine->proximity().lower();
  if (!(box_inset >= 0.0) || 2.0 * box_inset >= size.minCoeff()) {
    return absl::InvalidArgumentError(
        absl::StrFormat("box_inset: %g map units leaves no search box inside the map's %g x %g "
                        "rectangle (at most half its shorter side)",
                        box_inset, size.x(), size.y()));
  }
  return std::unique_ptr<WaypointObjective>(
      new WaypointObjective(problem, options.waypoints, box_inset, *std::move(engine)));
}

WaypointObjective::WaypointObjective(const Problem& problem, int waypoints, double box_inset,
                                     FitnessEngine engine)
    : start_(problem.start.head<2>()),
      goal_(problem.goal.head<2>()),
      waypoints_(waypoints),
      engine_(std::move(engine)) {
  const int k = waypoints;
  const Point2 inset(box_inset, box_inset);
  const Point2 lo = engine_.proximity().lower() + inset, hi = engine_.proximity().upper() - inset;
  lower_.resize(2 * k);
  upper_.resize(2 * k);
  lower_.head(k).setConstant(lo.x());
  lower_.tail(k).setConstant(lo.y());
  upper_.head(k).setConstant(hi.x());
  upper_.tail(k).setConstant(hi.y());
}

Path WaypointObjective::Decode(const Eigen::VectorXd& x) {
  Path path;
  engine_.Decode(x, path);
  return path;
}

void WaypointObjective::SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& x) const {
  const int k = waypoints_;
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
