#pragma once

#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/bench_options.h"
#include "bench/report.h"
#include "core/map/io/map_io.h"
#include "core/map/map.h"
#include "core/registry.h"

namespace swarmplan::bench {

// One start/goal problem on one map.
struct BenchProblem {
  std::string map_name;
  MapPtr map;
  std::string scenario;  // label for the CSV
  Point3 start = Point3::Zero();
  Point3 goal = Point3::Zero();
  std::optional<double> scen_optimal;  // the .scen file's 8-connected length, world units
  // The exact optimum (core/optimum.h) and why it is unknown when it is; see AddOptima.
  std::optional<double> optimal;
  std::string optimum_note;
};

// The chosen scenarios of a .scen file as problems on `map` (a grid of the scenarios' size):
// cells become world points at the cell centres, the .scen lengths are scaled to world units.
// INVALID_ARGUMENT naming the file when the map is not a grid or its size differs.
absl::StatusOr<std::vector<BenchProblem>> ScenarioProblems(const std::string& map_name,
                                                           const MapPtr& map,
                                                           const std::string& scen_name,
                                                           const std::vector<Scenario>& scenarios,
                                                           const ScenarioSelection& selection);

// Loads every --map (and its --scen) of the options into problems, map by map. Warnings (a
// .scen naming another map) go to `notes`.
absl::StatusOr<std::vector<BenchProblem>> LoadProblems(const BenchOptions& options,
                                                       std::ostream& notes);

// Fills each problem's exact optimum with the exact planner of its map kind, at most
// `budget` per problem, with the options' clearance; notes say where it stays unknown.
void AddOptima(const Registry& registry, absl::Duration budget, double clearance,
               std::vector<BenchProblem>& problems, std::ostream& notes);

// The planner ids to run on a map of `kind`: "all" expands to every planner supporting it;
// named planners are kept even when they do not support it (their runs then fail and say why).
// Without duplicates, in the order given (registry order for "all").
std::vector<std::string> PlannersFor(const Registry& registry,
                                     const std::vector<std::string>& requested, MapKind kind);

// Planner id -> its parameters, typed.
using PlannerParams = std::map<std::string, ParamValues>;

// Checks before any run: every named planner exists, and every --param names a selected planner
// and passes its schema. Returns the parameters typed by each planner's schema; the error
// message names the planner and parameter.
absl::StatusOr<PlannerParams> ResolvePlannerParams(const Registry& registry,
                                                   const BenchOptions& options);

// One run through RunPlan, as the server would make it, with the planner's `params`. A failed
// RunPlan gives a record with success = false and sets `note` to why; so does a path that is
// not collision-free.
RunRecord RunOnce(const Registry& registry, const BenchProblem& problem, const std::string& planner,
                  const ParamValues& params, uint64_t seed, const BenchOptions& options,
                  std::string* note);

// Every problem × planner × run, in that order; each record is handed to `on_record` as soon as
// it is made, notes go to `notes`.
void RunBench(const Registry& registry, const std::vector<BenchProblem>& problems,
              const BenchOptions& options, const PlannerParams& params,
              const std::function<void(const RunRecord&)>& on_record, std::ostream& notes);

}  // namespace swarmplan::bench
