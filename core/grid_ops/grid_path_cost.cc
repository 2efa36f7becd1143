#include "core/grid_ops/grid_path_cost.h"

#include <limits>
#include <utility>

#include "core/grid_ops/shortcut.h"
#include "core/path_metrics.h"
#include "core/smoothing/bounded_curvature.h"

namespace swarmplan {

absl::StatusOr<GridPathCost> GridPathCost::Create(const Problem& problem, const GridSpace& space) {
  const FleetObjective& fleet = problem.fleet;
  if (fleet.preferred_clearance <= 0.0 && fleet.turning_radius <= 0.0) {
    return GridPathCost(space, problem, nullptr);
  }
  WaypointFitnessOptions options;
  options.waypoints = 1;
  options.samples = 2;
  options.interpolation = Interpolation::kLinear;
  options.fleet = fleet;
  absl::StatusOr<FitnessEngine> engine = FitnessEngine::Create(problem, options);
  if (!engine.ok()) return engine.status();
  return GridPathCost(space, problem, std::make_unique<FitnessEngine>(*std::move(engine)));
}

GridPathCost::GridPathCost(const GridSpace& space, const Problem& problem,
                           std::unique_ptr<FitnessEngine> fleet)
    : space_(&space),
      preferred_clearance_(fleet ? problem.fleet.preferred_clearance : 0.0),
      clearance_weight_(problem.fleet.clearance_weight),
      turning_radius_(fleet ? problem.fleet.turning_radius : 0.0),
      clearance_(problem.clearance),
      fleet_(std::move(fleet)) {
  if (turning_radius_ > 0.0) checker_ = MakeCollisionChecker(*problem.map);
}

std::optional<Path> GridPathCost::PathOf(const std::vector<Cell>& cells) const {
  if (fleet_ == nullptr || preferred_clearance_ <= 0.0) return AnyAnglePath(*space_, cells);
  if (cells.empty()) return std::nullopt;
  return ShortcutKeepingClearance(*space_, space_->WorldPath(cells), fleet_->proximity().field(),
                                  preferred_clearance_, clearance_weight_);
}

double GridPathCost::Cost(const Path& path) {
  return fleet_ == nullptr ? PathLength(path) : fleet_->PathTerms(path).Total();
}

GridPathCost::Judged GridPathCost::Smoothed(const Path& path) {
  if (turning_radius_ <= 0.0) return {true, Cost(path)};
  BoundedCurvatureOptions options;
  options.turning_radius = turning_radius_;
  options.clearance = clearance_;
  const BoundedCurvatureResult smoothed = SmoothToTurningRadius(path, options, *checker_);
  // The plan keeps the raw path when the smoothing cannot keep the clearance.
  if (!smoothed.collision_free) return {false, Cost(path)};
  return {smoothed.corners_over == 0, Cost(smoothed.path)};
}

double GridPathCost::operator()(const std::vector<Cell>& cells) {
  const std::optional<Path> path = PathOf(cells);
  return path ? Cost(*path) : std::numeric_limits<double>::infinity();
}

}  // namespace swarmplan
