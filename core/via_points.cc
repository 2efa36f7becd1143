#include "core/via_points.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "core/fitness/path_objective_terms.h"
#include "core/path_metrics.h"
#include "core/random.h"

namespace swarmplan {
namespace {

// Passes a leg's iterations on as iterations of the whole plan.
class LegObserver final : public Observer {
 public:
  LegObserver(Observer& out, const IterationStats& before) : out_(out), before_(before) {}
  void OnIteration(const IterationStats& stats) override { out_.OnIteration(Shift(stats)); }
  IterationStats Shift(IterationStats stats) const {
    stats.iteration += before_.iteration;
    stats.best_fitness += before_.best_fitness;
    stats.mean_fitness += before_.best_fitness;
    stats.evaluations += before_.evaluations;
    stats.elapsed += before_.elapsed;
    return stats;
  }

 private:
  Observer& out_;
  IterationStats before_;  // iterations, fitness, evaluations and time of the legs before
};

// Appends `leg` to `path`, the leg's first point (the previous leg's last) once.
void Append(const Path& leg, Path& path) {
  path.insert(path.end(), leg.begin() + (path.empty() || leg.empty() ? 0 : 1), leg.end());
}

}  // namespace

std::vector<Problem> LegProblems(const PlanRequest& request) {
  std::vector<Point3> stops{request.problem.start};
  stops.insert(stops.end(), request.via_points.begin(), request.via_points.end());
  stops.push_back(request.problem.goal);
  std::vector<Problem> legs;
  for (size_t i = 0; i + 1 < stops.size(); ++i) {
    Problem leg = request.problem;
    leg.start = stops[i];
    leg.goal = stops[i + 1];
    leg.alternatives = 0;
    legs.push_back(std::move(leg));
  }
  return legs;
}

absl::StatusOr<PlanResult> RunThroughViaPoints(const Registry& registry, const PlanRequest& request,
                                               const StopToken& stop, Observer& observer) {
  const absl::Time start_time = absl::Now();
  const uint64_t seed = request.problem.seed != 0 ? request.problem.seed : PickSeed();
  const absl::Duration budget = request.problem.limits.time_budget;
  const std::vector<Problem> legs = LegProblems(request);

  PlanResult joined;
  joined.found = true;
  joined.seed = seed;
  IterationStats before;
  std::optional<FleetTerms> seed_objective = FleetTerms{};
  for (size_t k = 0; k < legs.size(); ++k) {
    PlanRequest leg = request;
    leg.via_points.clear();
    leg.vehicle = VehicleLimits{};
    leg.problem = legs[k];
    leg.problem.seed = seed + k != 0 ? seed + k : 1;
    if (budget != absl::InfiniteDuration()) {
      const absl::Duration left = budget - (absl::Now() - start_time);
      leg.problem.limits.time_budget =
          std::max(absl::ZeroDuration(), left / static_cast<int64_t>(legs.size() - k));
    }
    LegObserver shifted(observer, before);
    absl::StatusOr<PlanResult> result = RunPlan(registry, leg, stop, shifted);
    if (!result.ok()) return result.status();
    if (k == 0) {
      joined.algorithm = result->algorithm;
      joined.resolved_params = result->resolved_params;
      joined.smoothing = result->smoothing;
    }
    for (const IterationStats& s : result->convergence)
      joined.convergence.push_back(shifted.Shift(s));
    joined.iterations += result->iterations;
    joined.evaluations += result->evaluations;
    joined.cpu_time += result->cpu_time;
    joined.stop_reason = result->stop_reason;
    PlanResult::Leg& summary = joined.legs.emplace_back();
    summary.found = result->found;
    summary.fitness = result->fitness;
    summary.iterations = result->iterations;
    summary.metrics =
        result->smoothing_collision_free ? result->smoothed_metrics : result->raw_metrics;
    if (!result->found) {
      joined.found = false;
      break;
    }
    joined.best_iteration = before.iteration + result->best_iteration;
    before.iteration += result->iterations;
    before.best_fitness += result->fitness;
    before.evaluations += result->evaluations;
    before.elapsed = absl::Now() - start_time;
    joined.fitness += result->fitness;
    joined.smoothing_collision_free &= result->smoothing_collision_free;
    Append(result->raw_path, joined.raw_path);
    Append(result->smoothed_path, joined.smoothed_path);
    if (k + 1 < legs.size()) ++joined.via_points_reached;
    if (seed_objective && result->seed_objective) {
      seed_objective->length += result->seed_objective->length;
      seed_objective->clearance += result->seed_objective->clearance;
      seed_objective->curvature += result->seed_objective->curvature;
      seed_objective->violation += result->seed_objective->violation;
    } else {
      seed_objective.reset();
    }
    if (stop.Check(0) != StopReason::kNone) {
      if (k + 1 < legs.size()) joined.found = false;
      break;
    }
  }

  const Map& map = *request.problem.map;
  const Path& final_path = joined.smoothing_collision_free ? joined.smoothed_path : joined.raw_path;
  if (joined.found && !map.is_3d()) {
    absl::StatusOr<FleetTerms> terms = EvaluateFleetObjective(request.problem, final_path);
    if (!terms.ok()) return terms.status();
    joined.objective = *terms;
    joined.seed_objective = seed_objective;
  }
  if (joined.found && request.vehicle.timed()) {
    joined.timed_path = TimePath(final_path, request.vehicle);
  }
  joined.raw_metrics = EvaluatePath(map, joined.raw_path, request.problem.clearance);
  joined.smoothed_metrics = EvaluatePath(map, joined.smoothed_path, request.problem.clearance);
  joined.wall_time = absl::Now() - start_time;
  return joined;
}

Optimum CombineLegOptima(const std::vector<Optimum>& legs) {
  if (legs.size() == 1) return legs.front();
  Optimum sum;
  sum.known = !legs.empty();
  for (size_t k = 0; k < legs.size(); ++k) {
    const Optimum& leg = legs[k];
    sum.planner = leg.planner;
    if (!leg.known) {
      sum.known = false;
      sum.reason = absl::StrCat("leg ", k + 1, " of ", legs.size(), ": ", leg.reason);
      break;
    }
    sum.length += leg.length;
    sum.cost += leg.cost;
  }
  return sum;
}

}  // namespace swarmplan
