#include "core/run.h"

#include <time.h>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "core/fitness/path_objective_terms.h"
#include "core/geometry/collision.h"
#include "core/random.h"
#include "core/smoothing/smoothing.h"
#include "core/via_points.h"

namespace swarmplan {
namespace {

absl::Duration ThreadCpuTime() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return absl::Seconds(ts.tv_sec) + absl::Nanoseconds(ts.tv_nsec);
}

std::string FormatPoint(const Map& map, const Point3& p) {
  if (map.is_3d()) return absl::StrFormat("(%g, %g, %g)", p.x(), p.y(), p.z());
  return absl::StrFormat("(%g, %g)", p.x(), p.y());
}

absl::Status CheckEndpoint(const Map& map, const CollisionChecker& checker, const Point3& p,
                           double clearance, const char* field) {
  if (!p.allFinite()) {
    return absl::InvalidArgumentError(absl::StrCat(field, ": coordinates must be finite"));
  }
  const double c = checker.Clearance(p);
  if (c == -std::numeric_limits<double>::infinity()) {
    return absl::FailedPreconditionError(
        absl::StrCat(field, " ", FormatPoint(map, p), " is outside the map"));
  }
  // Touching an obstacle (clearance 0) counts as a collision, whatever the requested clearance.
  if (c <= 0.0 || c < clearance) {
    return absl::FailedPreconditionError(absl::StrFormat(
        "%s %s is inside an obstacle or closer than the clearance %g to one (clearance there: "
        "%g)",
        field, FormatPoint(map, p), clearance, std::max(c, 0.0)));
  }
  return absl::OkStatus();
}

}  // namespace

absl::Status ValidatePlanRequest(const Registry& registry, const PlanRequest& request) {
  absl::StatusOr<const PlannerInfo*> info = registry.Get(request.algorithm);
  if (!info.ok()) return info.status();
  absl::StatusOr<ParamSet> params = ParamSet::Resolve((*info)->params, request.params);
  if (!params.ok()) return params.status();
  const Problem& problem = request.problem;
  if (problem.map == nullptr) return absl::InvalidArgumentError("map: no map given");
  const Map& map = *problem.map;
  if (!(*info)->Supports(map.kind())) {
    return absl::FailedPreconditionError(absl::StrCat(
        "algorithm '", request.algorithm, "' cannot plan on a ", MapKindName(map.kind()),
        " map; it accepts: ", JoinMapKinds((*info)->map_kinds)));
  }
  if (!std::isfinite(problem.clearance) || problem.clearance < 0) {
    return absl::InvalidArgumentError("clearance: must be a finite number >= 0");
  }
  if (absl::Status s = ValidateFleetObjective(problem.fleet); !s.ok()) return s;
  if (absl::Status s = ValidateVehicleLimits(request.vehicle); !s.ok()) return s;
  if (problem.alternatives < 0 || problem.alternatives > kMaxAlternatives) {
    return absl::InvalidArgumentError(absl::StrCat(
        "alternatives: must be in [0, ", kMaxAlternatives, "], got ", problem.alternatives));
  }
  if (request.via_points.size() > static_cast<size_t>(kMaxViaPoints)) {
    return absl::InvalidArgumentError(
        absl::StrCat("via_points: at most ", kMaxViaPoints, ", got ", request.via_points.size()));
  }
  if (problem.limits.max_iterations < 0) {
    return absl::InvalidArgumentError("limits.max_iterations: must be >= 0");
  }
  bool known_smoothing = false;
  for (const std::string& m : SmoothingMethods()) known_smoothing |= m == request.smoothing;
  if (!known_smoothing && !request.smoothing.empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat("smoothing: unknown method '", request.smoothing, "'"));
  }
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(map);
  if (absl::Status s = CheckEndpoint(map, *checker, problem.start, problem.clearance, "start");
      !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckEndpoint(map, *checker, problem.goal, problem.clearance, "goal");
      !s.ok()) {
    return s;
  }
  for (size_t i = 0; i < request.via_points.size(); ++i) {
    const std::string field = absl::StrCat("via_points[", i, "]");
    if (absl::Status s =
            CheckEndpoint(map, *checker, request.via_points[i], problem.clearance, field.c_str());
        !s.ok()) {
      return s;
    }
  }
  const std::unique_ptr<Planner> planner = (*info)->factory(*params);
  if (absl::Status s = planner->CheckProblem(problem); !s.ok()) {
    return absl::Status(s.code(), absl::StrCat("algorithm '", request.algorithm,
                                               "' cannot plan this request: ", s.message()));
  }
  return absl::OkStatus();
}

absl::StatusOr<PlanResult> RunPlan(const Registry& registry, const PlanRequest& request,
                                   const StopToken& stop, Observer& observer) {
  if (absl::Status s = ValidatePlanRequest(registry, request); !s.ok()) return s;
  if (!request.via_points.empty()) return RunThroughViaPoints(registry, request, stop, observer);
  const PlannerInfo& info = **registry.Get(request.algorithm);
  absl::StatusOr<ParamSet> params = ParamSet::Resolve(info.params, request.params);
  if (!params.ok()) return params.status();
  std::unique_ptr<Planner> planner = info.factory(*params);

  Problem problem = request.problem;
  if (problem.seed == 0) problem.seed = PickSeed();
  StopToken bounded = stop.WithMaxIterations(problem.limits.max_iterations);
  const absl::Time start_time = absl::Now();
  if (problem.limits.time_budget != absl::InfiniteDuration()) {
    bounded = bounded.WithDeadline(start_time + problem.limits.time_budget);
  }

  const absl::Duration cpu_start = ThreadCpuTime();
  absl::StatusOr<SearchResult> search = planner->Solve(problem, bounded, observer);
  if (!search.ok()) return search.status();

  PlanResult result;
  result.algorithm = info.id;
  result.found = search->found;
  result.raw_path = std::move(search->path);
  result.fitness = search->fitness;
  result.iterations = search->iterations;
  result.evaluations = search->evaluations;
  result.best_iteration = search->best_iteration;
  result.stop_reason = search->stop_reason;
  result.convergence = std::move(search->convergence);
  result.seed = problem.seed;
  result.resolved_params = params->values();
  result.smoothing = request.smoothing.empty() ? "none" : request.smoothing;

  const Map& map = *problem.map;
  bool within_turning_radius = true;
  if (!result.raw_path.empty()) {
    absl::StatusOr<SmoothingResult> smoothed = Smooth(
        result.smoothing, map, result.raw_path, problem.clearance, problem.fleet.turning_radius);
    if (!smoothed.ok()) return smoothed.status();
    result.smoothed_path = std::move(smoothed->path);
    result.smoothing_collision_free = smoothed->collision_free;
    within_turning_radius = smoothed->within_turning_radius;
  }
  if (!map.is_3d() && result.found) {
    const Path& final_path =
        result.smoothing_collision_free ? result.smoothed_path : result.raw_path;
    absl::StatusOr<FleetTerms> terms = EvaluateFleetObjective(problem, final_path);
    if (!terms.ok()) return terms.status();
    result.objective = *terms;
  }
  if (!map.is_3d() && !search->seed_path.empty()) {
    absl::StatusOr<SmoothingResult> seed = Smooth(result.smoothing, map, search->seed_path,
                                                  problem.clearance, problem.fleet.turning_radius);
    if (!seed.ok()) return seed.status();
    absl::StatusOr<FleetTerms> terms =
        EvaluateFleetObjective(problem, seed->collision_free ? seed->path : search->seed_path);
    if (!terms.ok()) return terms.status();
    result.seed_objective = *terms;
    // A seeded plan is never worse than its best seed: when the seed, after the same smoothing,
    // is better by the objective than the search's path after it, or keeps the clearance and
    // the turning radius after it where the search's path does not, the seed is the result.
    const bool seed_meets = seed->collision_free && seed->within_turning_radius;
    const bool path_meets = result.smoothing_collision_free && within_turning_radius;
    if (result.found && result.objective && seed->collision_free &&
        (seed_meets != path_meets ? seed_meets : terms->Total() < result.objective->Total())) {
      absl::StatusOr<FleetTerms> raw = EvaluateFleetObjective(problem, search->seed_path);
      if (!raw.ok()) return raw.status();
      result.raw_path = search->seed_path;
      result.smoothed_path = std::move(seed->path);
      result.smoothing_collision_free = true;
      result.objective = *terms;
      result.fitness = raw->Total();
      result.best_iteration = 0;
    }
  }
  for (SearchResult::Alternative& alternative : search->alternatives) {
    PlanResult::Alternative& out = result.alternatives.emplace_back();
    out.metrics = EvaluatePath(map, alternative.path, problem.clearance);
    out.path = std::move(alternative.path);
    out.fitness = alternative.fitness;
  }
  if (request.vehicle.timed() && result.found) {
    result.timed_path = TimePath(
        result.smoothing_collision_free ? result.smoothed_path : result.raw_path, request.vehicle);
  }
  result.raw_metrics = EvaluatePath(map, result.raw_path, problem.clearance);
  result.smoothed_metrics = EvaluatePath(map, result.smoothed_path, problem.clearance);
  result.wall_time = absl::Now() - start_time;
  result.cpu_time = ThreadCpuTime() - cpu_start;
  return result;
}

void SetOptimum(const Map& map, Optimum optimum, PlanResult& result) {
  result.optimum = std::move(optimum);
  const Path& final_path = result.smoothing_collision_free && !result.smoothed_path.empty()
                               ? result.smoothed_path
                               : result.raw_path;
  result.optimality_ratio =
      result.found ? OptimalityRatio(PlanCost(map, final_path), result.optimum) : 0.0;
  for (PlanResult::Alternative& alternative : result.alternatives) {
    alternative.optimality_ratio = OptimalityRatio(PlanCost(map, alternative.path), result.optimum);
  }
}

}  // namespace swarmplan
