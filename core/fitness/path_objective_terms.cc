#include "core/fitness/path_objective_terms.h"

#include "absl/status/status.h"
#include "core/fitness/fitness_engine.h"

namespace swarmplan {

absl::StatusOr<FleetTerms> EvaluateFleetObjective(const Problem& problem, const Path& path) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("map: no map given");
  if (problem.map->is_3d()) {
    return absl::FailedPreconditionError("the fleet objective is defined on 2D maps only");
  }
  WaypointFitnessOptions options;
  options.waypoints = 1;
  options.samples = 2;
  options.interpolation = Interpolation::kLinear;
  options.fleet = problem.fleet;
  absl::StatusOr<FitnessEngine> engine = FitnessEngine::Create(problem, options);
  if (!engine.ok()) return engine.status();
  return engine->PathTerms(path);
}

}  // namespace swarmplan
