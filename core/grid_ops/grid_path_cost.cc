#include "core/grid_ops/grid_path_cost.h"

#include <limits>
#include <utility>

#include "core/grid_ops/shortcut.h"
#include "core/path_metrics.h"

namespace swarmplan {

absl::StatusOr<GridPathCost> GridPathCost::Create(const Problem& problem, const GridSpace& space) {
  const FleetObjective& fleet = problem.fleet;
  if (fleet.preferred_clearance <= 0.0 && fleet.turning_radius <= 0.0) {
    return GridPathCost(space, 0.0, nullptr);
  }
  WaypointFitnessOptions options;
  options.waypoints = 1;
  options.samples = 2;
  options.interpolation = Interpolation::kLinear;
  options.fleet = fleet;
  absl::StatusOr<FitnessEngine> engine = FitnessEngine::Create(problem, options);
  if (!engine.ok()) return engine.status();
  return GridPathCost(space, fleet.preferred_clearance,
                      std::make_unique<FitnessEngine>(*std::move(engine)));
}

GridPathCost::GridPathCost(const GridSpace& space, double preferred_clearance,
                           std::unique_ptr<FitnessEngine> fleet)
    : space_(&space), preferred_clearance_(preferred_clearance), fleet_(std::move(fleet)) {}

std::optional<Path> GridPathCost::PathOf(const std::vector<Cell>& cells) const {
  if (fleet_ == nullptr || preferred_clearance_ <= 0.0) return AnyAnglePath(*space_, cells);
  if (cells.empty()) return std::nullopt;
  return ShortcutKeepingClearance(*space_, space_->WorldPath(cells), fleet_->proximity().field(),
                                  preferred_clearance_);
}

double GridPathCost::Cost(const Path& path) {
  return fleet_ == nullptr ? PathLength(path) : fleet_->PathTerms(path).Total();
}

double GridPathCost::operator()(const std::vector<Cell>& cells) {
  const std::optional<Path> path = PathOf(cells);
  return path ? Cost(*path) : std::numeric_limits<double>::infinity();
}

}  // namespace swarmplan
