#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/scenario_selection.h"
#include "core/fitness/fleet_objective.h"
#include "core/map/point.h"
#include "core/params.h"

namespace swarmplan::bench {

// Planner id -> parameter name -> value as given; typed against each planner's schema later.
using RawParams = std::map<std::string, std::map<std::string, std::string>>;

// What `swarmplan-bench` was asked to do, as given on the command line.
struct BenchOptions {
  std::vector<std::string> planners;  // ids; "all" means every planner supporting the map
  std::vector<std::string> maps;
  std::string format;                       // "" guesses from each map's extension
  std::vector<std::string> scenario_files;  // one per map, in order; or none
  ScenarioSelection scenario_selection;
  std::optional<Point3> start;  // world coordinates, used when there are no scenario files
  std::optional<Point3> goal;
  int runs = 1;
  uint64_t seed = 1;
  RawParams params;
  int max_iterations = 0;  // 0: each planner's default
  std::optional<double> time_budget_seconds;
  double clearance = 0.0;
  // The fleet objective's preferences of every problem (Problem::fleet).
  FleetObjective fleet;
  int alternatives = 0;  // PlanRequest.alternatives: paths in other corridors asked for
  double optimum_budget_seconds = 10.0;  // per problem, for the exact optimum; 0: none
  std::string smoothing = "none";
  std::string csv_path;              // "" for stdout
  std::string convergence_csv_path;  // "" for none
  std::string markdown_path;
  // OMPL's benchmark log: FILE for one problem; FILE-1, FILE-2, ... (before its extension)
  // for several, one experiment each. "" for none.
  std::string ompl_log_path;
  bool list_planners = false;
};

struct ParsedArgs {
  BenchOptions options;
  std::string help;  // non-empty when --help was asked for: print it and exit 0
};

// Parses the command line (argv[0] is the program name). INVALID_ARGUMENT with a message naming
// the option on bad arguments.
absl::StatusOr<ParsedArgs> ParseBenchArgs(int argc, const char* const* argv);

// "X,Y" or "X,Y,Z" (Z defaults to 0).
absl::StatusOr<Point3> ParsePoint(const std::string& text);

// A parameter's text as the value of its declared type: "true"/"false" for bool, an integer for
// int, a number for double, the text itself for an enum. INVALID_ARGUMENT otherwise.
absl::StatusOr<ParamValue> ParseParamValue(const std::string& text, ParamType type);

// Adds one "PLANNER.NAME=VALUE" assignment to `params`.
absl::Status AddParamAssignment(const std::string& text, RawParams& params);

// "all" or a positive count, for --scenarios.
absl::StatusOr<ScenarioSelection> ParseScenarioCount(const std::string& text);

}  // namespace swarmplan::bench
