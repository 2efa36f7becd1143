#include "bench/bench_options.h"

#include <cmath>
#include <limits>
#include <vector>

#include "CLI/CLI.hpp"
#include "absl/status/status.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"
#include "core/map/io/map_io.h"
#include "core/problem.h"
#include "core/smoothing/smoothing.h"

namespace swarmplan::bench {
namespace {

constexpr char kDescription[] =
    "Runs registered planners on maps and writes one CSV row per run, plus an optional Markdown "
    "summary per planner and map.\n"
    "Example: swarmplan-bench --planner astar --map arena.map --scen arena.map.scen";

absl::Status Invalid(const std::string& message) { return absl::InvalidArgumentError(message); }

}  // namespace

absl::StatusOr<Point3> ParsePoint(const std::string& text) {
  const std::vector<std::string> parts = absl::StrSplit(text, ',');
  if (parts.size() != 2 && parts.size() != 3) {
    return Invalid(absl::StrCat("'", text, "' is not a point: expected X,Y or X,Y,Z"));
  }
  Point3 p = Point3::Zero();
  for (size_t i = 0; i < parts.size(); ++i) {
    double v = 0;
    if (!absl::SimpleAtod(parts[i], &v) || !std::isfinite(v)) {
      return Invalid(
          absl::StrCat("'", text, "' is not a point: '", parts[i], "' is not a finite number"));
    }
    p[static_cast<int>(i)] = v;
  }
  return p;
}

absl::StatusOr<ParamValue> ParseParamValue(const std::string& text, ParamType type) {
  switch (type) {
    case ParamType::kBool:
      if (text == "true") return true;
      if (text == "false") return false;
      break;
    case ParamType::kInt:
      if (int64_t i = 0; absl::SimpleAtoi(text, &i)) return i;
      break;
    case ParamType::kDouble:
      if (double d = 0; absl::SimpleAtod(text, &d)) return d;
      break;
    case ParamType::kEnum:
      return text;
  }
  return Invalid(absl::StrCat("'", text, "' is not a valid ", ParamTypeName(type),
                              type == ParamType::kBool ? " (true or false)" : ""));
}

absl::Status AddParamAssignment(const std::string& text, RawParams& params) {
  const size_t eq = text.find('=');
  const size_t dot = text.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 ||
      dot + 1 == eq) {
    return Invalid(absl::StrCat("--param '", text,
                                "': expected PLANNER.NAME=VALUE, e.g. astar.diagonal=true"));
  }
  const std::string planner = text.substr(0, dot);
  const std::string name = text.substr(dot + 1, eq - dot - 1);
  const std::string value = text.substr(eq + 1);
  if (value.empty()) return Invalid(absl::StrCat("--param '", text, "': the value is empty"));
  params[planner][name] = value;
  return absl::OkStatus();
}

absl::StatusOr<ScenarioSelection> ParseScenarioCount(const std::string& text) {
  if (text == "all") return ScenarioSelection{ScenarioSelection::Mode::kAll, 0};
  int n = 0;
  if (!absl::SimpleAtoi(text, &n) || n < 1) {
    return Invalid(absl::StrCat("--scenarios: '", text, "' is neither 'all' nor a count >= 1"));
  }
  return ScenarioSelection{ScenarioSelection::Mode::kEvenly, n};
}

absl::StatusOr<ParsedArgs> ParseBenchArgs(int argc, const char* const* argv) {
  ParsedArgs parsed;
  BenchOptions& o = parsed.options;
  std::string start, goal, scenarios;
  std::vector<std::string> param_assignments;
  double time_budget = 0;

  CLI::App app(kDescription, "swarmplan-bench");
  app.add_option("--planner", o.planners,
                 "Planner id (repeatable), or 'all' for every planner supporting the map");
  app.add_flag("--list-planners", o.list_planners, "List the registered planners and exit");
  app.add_option("--map", o.maps, "Map file (repeatable)");
  app.add_option("--format", o.format,
                 "Map format for every --map (default: guessed from the extension)")
      ->check(CLI::IsMember(MapFormats()));
  CLI::Option* scen = app.add_option("--scen", o.scenario_files,
                                     "Moving AI .scen file (repeatable: one per --map, in order)");
  CLI::Option* count = app.add_option(
      "--scenarios", scenarios, "Run N scenarios spread evenly over each .scen file, or 'all'");
  CLI::Option* per_bucket =
      app.add_option("--bucket-sample", o.scenario_selection.count,
                     "Run K scenarios from every bucket of each .scen file (the default, K=1)")
          ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  count->excludes(per_bucket);
  CLI::Option* start_opt =
      app.add_option("--start", start, "Start X,Y[,Z] in world coordinates (without --scen)");
  CLI::Option* goal_opt =
      app.add_option("--goal", goal, "Goal X,Y[,Z] in world coordinates (without --scen)");
  start_opt->needs(goal_opt)->excludes(scen);
  goal_opt->needs(start_opt)->excludes(scen);
  app.add_option("--runs", o.runs, "Runs per scenario and planner (seeds S, S+1, ...)")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  app.add_option("--seed", o.seed, "First seed (>= 1)")
      ->check(CLI::Range(uint64_t{1}, std::numeric_limits<uint64_t>::max()));
  app.add_option("--param", param_assignments, "Planner parameter PLANNER.NAME=VALUE (repeatable)");
  app.add_option("--max-iterations", o.max_iterations,
                 "Iteration cap per run (0: the planner's default)")
      ->check(CLI::NonNegativeNumber);
  CLI::Option* budget = app.add_option("--time-budget", time_budget, "Time budget per run, seconds")
                            ->check(CLI::PositiveNumber);
  app.add_option("--clearance", o.clearance, "Clearance from obstacles, world units")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--preferred-clearance", o.fleet.preferred_clearance,
                 "Preferred clearance of the fleet objective, world units (0: none)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--turning-radius", o.fleet.turning_radius,
                 "Turning radius of the fleet objective, world units (0: none)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--clearance-weight", o.fleet.clearance_weight,
                 "Weight of the shortfall below the preferred clearance")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--curvature-weight", o.fleet.curvature_weight,
                 "Weight of the curvature above 1 / turning radius")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--alternatives", o.alternatives,
                 "Paths in other corridors each plan returns besides its own, as K - 1 of "
                 "PlanRequest.alternatives = K (0: none)")
      ->check(CLI::Range(0, kMaxAlternatives - 1));
  app.add_option("--optimum-budget", o.optimum_budget_seconds,
                 "Seconds per problem for its exact optimum, the `optimal` column (0: none)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--smoothing", o.smoothing, "Smoothing applied to every path")
      ->check(CLI::IsMember(SmoothingMethods()));
  app.add_option("--csv", o.csv_path, "CSV output file (default: stdout)");
  app.add_option("--convergence-csv", o.convergence_csv_path,
                 "also write each run's best per iteration and its seconds to this CSV");
  app.add_option("--markdown", o.markdown_path, "Markdown summary file");
  app.add_option("--ompl-log", o.ompl_log_path,
                 "OMPL benchmark log (for ompl_benchmark_statistics.py and Planner Arena), one "
                 "experiment per problem: FILE, or FILE-1, FILE-2, ... for several problems");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    parsed.help = app.help();
    return parsed;
  } catch (const CLI::Error& e) {
    return Invalid(e.what());
  }

  if (o.list_planners) return parsed;
  if (o.planners.empty()) return Invalid("no planner given: use --planner ID (or --planner all)");
  if (o.maps.empty()) return Invalid("no map given: use --map FILE");
  if (!o.scenario_files.empty() && o.scenario_files.size() != o.maps.size()) {
    return Invalid(absl::StrCat("--scen given ", o.scenario_files.size(), " times for ",
                                o.maps.size(), " --map: give one .scen file per map, in order"));
  }
  if (o.scenario_files.empty() && start.empty()) {
    return Invalid("no problem given: use --scen FILE, or --start X,Y --goal X,Y");
  }
  if (o.scenario_files.empty() && (!scenarios.empty() || per_bucket->count() > 0)) {
    return Invalid("--scenarios and --bucket-sample need --scen");
  }
  if (!scenarios.empty()) {
    absl::StatusOr<ScenarioSelection> selection = ParseScenarioCount(scenarios);
    if (!selection.ok()) return selection.status();
    o.scenario_selection = *selection;
  }
  if (!start.empty()) {
    absl::StatusOr<Point3> s = ParsePoint(start);
    if (!s.ok()) return Invalid(absl::StrCat("--start: ", s.status().message()));
    absl::StatusOr<Point3> g = ParsePoint(goal);
    if (!g.ok()) return Invalid(absl::StrCat("--goal: ", g.status().message()));
    o.start = *s;
    o.goal = *g;
  }
  for (const std::string& assignment : param_assignments) {
    if (absl::Status s = AddParamAssignment(assignment, o.params); !s.ok()) return s;
  }
  if (budget->count() > 0) o.time_budget_seconds = time_budget;
  return parsed;
}

}  // namespace swarmplan::bench
