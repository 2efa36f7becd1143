#include "bench/bench_runner.h"

#include <algorithm>
#include <filesystem>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "core/geometry/homotopy.h"
#include "core/optimum.h"
#include "core/run.h"
#include "core/stop_token.h"

namespace swarmplan::bench {
namespace {

std::string FileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

std::string PointLabel(const Point3& p, bool is_3d) {
  if (is_3d) return absl::StrFormat("%g %g %g", p.x(), p.y(), p.z());
  return absl::StrFormat("%g %g", p.x(), p.y());
}

// Each iteration's best and when, from the plan's start, it first came within 1.05 and 1.02 of
// the optimum.
class QualityClock final : public Observer {
 public:
  QualityClock(absl::Time started, std::optional<double> optimal)
      : started_(started), optimal_(optimal) {}
  void OnIteration(const IterationStats& stats) override {
    const double seconds = absl::ToDoubleSeconds(absl::Now() - started_);
    progress.push_back({seconds, stats.best_fitness, stats.feasible});
    if (!optimal_ || !stats.feasible) return;
    if (!to_1_05 && stats.best_fitness <= 1.05 * *optimal_) to_1_05 = seconds;
    if (!to_1_02 && stats.best_fitness <= 1.02 * *optimal_) to_1_02 = seconds;
  }
  std::optional<double> to_1_05, to_1_02;
  std::vector<RunRecord::Progress> progress;

 private:
  absl::Time started_;
  std::optional<double> optimal_;
};

}  // namespace

absl::StatusOr<std::vector<BenchProblem>> ScenarioProblems(const std::string& map_name,
                                                           const MapPtr& map,
                                                           const std::string& scen_name,
                                                           const std::vector<Scenario>& scenarios,
                                                           const ScenarioSelection& selection) {
  const OccupancyGrid* grid = map->grid();
  if (grid == nullptr) {
    return absl::InvalidArgumentError(absl::StrCat(scen_name, ": scenarios need a grid map, but ",
                                                   map_name, " is a ", MapKindName(map->kind()),
                                                   " map"));
  }
  std::vector<BenchProblem> problems;
  for (size_t index : SelectScenarios(scenarios, selection)) {
    const Scenario& s = scenarios[index];
    if (s.width != grid->width() || s.height != grid->height()) {
      return absl::InvalidArgumentError(
          absl::StrFormat("%s: scenario %d is for a %dx%d map, but %s is %dx%d", scen_name, index,
                          s.width, s.height, map_name, grid->width(), grid->height()));
    }
    BenchProblem p;
    p.map_name = map_name;
    p.map = map;
    p.scenario = absl::StrCat(index);
    const Point2 start = grid->CellCenter(s.start);
    const Point2 goal = grid->CellCenter(s.goal);
    p.start = Point3(start.x(), start.y(), 0.0);
    p.goal = Point3(goal.x(), goal.y(), 0.0);
    p.scen_optimal = s.optimal_length * grid->resolution();
    problems.push_back(std::move(p));
  }
  return problems;
}

absl::StatusOr<std::vector<BenchProblem>> LoadProblems(const BenchOptions& options,
                                                       std::ostream& notes) {
  std::vector<BenchProblem> problems;
  for (size_t i = 0; i < options.maps.size(); ++i) {
    const std::string& path = options.maps[i];
    absl::StatusOr<Map> loaded = LoadMapFile(path, options.format);
    if (!loaded.ok()) return loaded.status();
    const MapPtr map = std::make_shared<const Map>(*std::move(loaded));
    const std::string map_name = FileName(path);

    if (options.scenario_files.empty()) {
      BenchProblem p;
      p.map_name = map_name;
      p.map = map;
      p.start = *options.start;
      p.goal = *options.goal;
      p.scenario = absl::StrCat("(", PointLabel(p.start, map->is_3d()), ")->(",
                                PointLabel(p.goal, map->is_3d()), ")");
      problems.push_back(std::move(p));
      continue;
    }
    const std::string& scen_path = options.scenario_files[i];
    absl::StatusOr<std::vector<Scenario>> scenarios = LoadScenarioFile(scen_path);
    if (!scenarios.ok()) return scenarios.status();
    if (!scenarios->empty() && FileName((*scenarios)[0].map_name) != map_name) {
      notes << "note: " << scen_path << " names map '" << (*scenarios)[0].map_name
            << "', running it on " << path << "\n";
    }
    absl::StatusOr<std::vector<BenchProblem>> from_scen = ScenarioProblems(
        map_name, map, FileName(scen_path), *scenarios, options.scenario_selection);
    if (!from_scen.ok()) return from_scen.status();
    problems.insert(problems.end(), std::make_move_iterator(from_scen->begin()),
                    std::make_move_iterator(from_scen->end()));
  }
  return problems;
}

std::vector<std::string> PlannersFor(const Registry& registry,
                                     const std::vector<std::string>& requested, MapKind kind) {
  std::vector<std::string> ids;
  auto add = [&ids](const std::string& id) {
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  };
  for (const std::string& id : requested) {
    if (id != "all") {
      add(id);
      continue;
    }
    for (const PlannerInfo& info : registry.planners()) {
      if (info.Supports(kind)) add(info.id);
    }
  }
  return ids;
}

absl::StatusOr<PlannerParams> ResolvePlannerParams(const Registry& registry,
                                                   const BenchOptions& options) {
  const bool all =
      std::find(options.planners.begin(), options.planners.end(), "all") != options.planners.end();
  for (const std::string& id : options.planners) {
    if (id == "all") continue;
    if (absl::StatusOr<const PlannerInfo*> info = registry.Get(id); !info.ok()) {
      return absl::InvalidArgumentError(absl::StrCat("--planner: ", info.status().message()));
    }
  }
  PlannerParams typed;
  for (const auto& [id, raw] : options.params) {
    absl::StatusOr<const PlannerInfo*> info = registry.Get(id);
    if (!info.ok()) {
      return absl::InvalidArgumentError(absl::StrCat("--param: ", info.status().message()));
    }
    if (!all &&
        std::find(options.planners.begin(), options.planners.end(), id) == options.planners.end()) {
      return absl::InvalidArgumentError(
          absl::StrCat("--param: planner '", id, "' is not among the --planner ids"));
    }
    ParamValues& values = typed[id];
    for (const auto& [name, text] : raw) {
      const auto spec = std::find_if((*info)->params.begin(), (*info)->params.end(),
                                     [&name](const ParamSpec& s) { return s.name == name; });
      if (spec == (*info)->params.end()) {
        values[name] = text;  // unknown: ParamSet::Resolve names it with the accepted ones
        continue;
      }
      absl::StatusOr<ParamValue> value = ParseParamValue(text, spec->type);
      if (!value.ok()) {
        return absl::InvalidArgumentError(
            absl::StrCat("--param ", id, ".", name, ": ", value.status().message()));
      }
      values[name] = *std::move(value);
    }
    if (absl::StatusOr<ParamSet> set = ParamSet::Resolve((*info)->params, values); !set.ok()) {
      return absl::InvalidArgumentError(
          absl::StrCat("--param for '", id, "': ", set.status().message()));
    }
  }
  return typed;
}

void AddOptima(const Registry& registry, absl::Duration budget, double clearance,
               std::vector<BenchProblem>& problems, std::ostream& notes) {
  for (BenchProblem& p : problems) {
    Problem problem;
    problem.map = p.map;
    problem.start = p.start;
    problem.goal = p.goal;
    problem.clearance = clearance;
    const Optimum optimum = ComputeOptimum(registry, problem, budget);
    if (optimum.known) {
      p.optimal = optimum.cost;
      continue;
    }
    p.optimal.reset();
    p.optimum_note = optimum.reason;
    notes << "note: " << p.map_name << " scenario " << p.scenario << ": no exact optimum ("
          << optimum.planner << ": " << optimum.reason << ")\n";
  }
}

RunRecord RunOnce(const Registry& registry, const BenchProblem& problem, const std::string& planner,
                  const ParamValues& params, uint64_t seed, const BenchOptions& options,
                  std::string* note) {
  PlanRequest request;
  request.algorithm = planner;
  request.params = params;
  request.problem.map = problem.map;
  request.problem.start = problem.start;
  request.problem.goal = problem.goal;
  request.problem.clearance = options.clearance;
  request.problem.fleet = options.fleet;
  if (options.alternatives > 0) request.problem.alternatives = options.alternatives + 1;
  request.problem.limits.max_iterations = options.max_iterations;
  if (options.time_budget_seconds) {
    request.problem.limits.time_budget = absl::Seconds(*options.time_budget_seconds);
  }
  request.problem.seed = seed;
  request.smoothing = options.smoothing;

  RunRecord record;
  record.map = problem.map_name;
  record.scenario = problem.scenario;
  record.planner = planner;
  record.seed = seed;
  record.optimal = problem.optimal;
  record.scen_optimal = problem.scen_optimal;

  const absl::Time started = absl::Now();
  QualityClock observer(started, problem.optimal);
  absl::StatusOr<PlanResult> result = RunPlan(registry, request, StopToken(), observer);
  if (!result.ok()) {
    record.wall_seconds = absl::ToDoubleSeconds(absl::Now() - started);
    *note = result.status().ToString();
    return record;
  }
  const PathMetrics& metrics = result->smoothed_metrics;
  const bool has_path = !result->smoothed_path.empty();
  record.success = result->found && has_path && metrics.collision_free;
  if (has_path) {
    record.length = metrics.length;
    record.min_clearance = metrics.min_clearance;
    record.max_curvature = metrics.max_curvature;
  }
  if (result->found && has_path && !metrics.collision_free) {
    *note = "the planner reported a path that is not collision-free (counted as a failure)";
  }
  // The optimum's cost is its length on 2D maps and the terrain objective on terrain.
  record.ratio =
      LengthRatio(record.success,
                  has_path ? std::optional<double>(PlanCost(*problem.map, result->smoothed_path))
                           : std::nullopt,
                  record.optimal);
  record.iterations = result->iterations;
  record.evaluations = result->evaluations;
  record.fitness = result->fitness;
  if (!result->convergence.empty())
    record.initial_fitness = result->convergence.front().best_fitness;
  record.best_iteration = result->best_iteration;
  if (result->objective) record.objective = result->objective->Total();
  if (result->seed_objective) {
    record.seed_objective = result->seed_objective->Total();
    record.seed_penalty = result->seed_objective->Total() - result->seed_objective->length;
  }
  if (options.alternatives > 0 && record.success) {
    // Valid alternatives, and how many of the paths (the result first) lie pairwise in
    // distinct corridors by an independent test.
    std::vector<const Path*> distinct = {&result->smoothed_path};
    int valid = 0;
    for (const PlanResult::Alternative& alternative : result->alternatives) {
      if (!alternative.metrics.collision_free) continue;
      ++valid;
      const bool separated = std::all_of(distinct.begin(), distinct.end(), [&](const Path* kept) {
        return SeparatedByObstacle(*problem.map, *kept, alternative.path);
      });
      if (separated) distinct.push_back(&alternative.path);
    }
    record.alternatives = valid;
    record.distinct_corridors = static_cast<int>(distinct.size());
  }
  record.seconds_to_1_05 = observer.to_1_05;
  record.seconds_to_1_02 = observer.to_1_02;
  record.convergence = std::move(observer.progress);
  record.wall_seconds = absl::ToDoubleSeconds(result->wall_time);
  return record;
}

void RunBench(const Registry& registry, const std::vector<BenchProblem>& problems,
              const BenchOptions& options, const PlannerParams& params,
              const std::function<void(const RunRecord&)>& on_record, std::ostream& notes) {
  static const ParamValues kNoParams;
  const Map* noted_map = nullptr;  // say once per map that nothing runs on it
  for (const BenchProblem& problem : problems) {
    const std::vector<std::string> planners =
        PlannersFor(registry, options.planners, problem.map->kind());
    if (planners.empty() && noted_map != problem.map.get()) {
      noted_map = problem.map.get();
      notes << "note: no selected planner supports " << problem.map_name << " (a "
            << MapKindName(problem.map->kind()) << " map)\n";
    }
    for (const std::string& planner : planners) {
      const auto given = params.find(planner);
      const ParamValues& planner_params = given == params.end() ? kNoParams : given->second;
      for (int run = 0; run < options.runs; ++run) {
        const uint64_t seed = options.seed + static_cast<uint64_t>(run);
        std::string note;
        const RunRecord record =
            RunOnce(registry, problem, planner, planner_params, seed, options, &note);
        if (!note.empty()) {
          notes << "note: " << problem.map_name << " scenario " << problem.scenario << ", "
                << planner << ", seed " << seed << ": " << note << "\n";
        }
        on_record(record);
      }
    }
  }
}

}  // namespace swarmplan::bench
