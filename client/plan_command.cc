// swarmplan plan MAP_ID --start x,y --goal x,y [--algorithm ID] [--param NAME=VALUE]...
#include <iostream>
#include <memory>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/arguments.h"
#include "client/commands.h"
#include "client/exit_codes.h"
#include "client/job_follow.h"
#include "client/map_reference.h"
#include "client/output.h"
#include "client/path_files.h"
#include "swarmplan/v1/algorithms.grpc.pb.h"
#include "swarmplan/v1/jobs.grpc.pb.h"

namespace swarmplan::client {
namespace {

struct PlanOptions {
  std::string map;  // an id or NAME@VERSION
  std::string start;
  std::string goal;
  std::string algorithm = "astar";
  std::vector<std::string> params;
  uint64_t seed = 0;
  double clearance = 0.0;
  double preferred_clearance = 0.0;
  double turning_radius = 0.0;
  double max_speed = 0.0;
  double max_acceleration = 0.0;
  double max_yaw_rate = 0.0;
  int alternatives = 0;
  int max_iterations = 0;
  std::string time_budget;
  std::string smoothing;
  std::vector<std::string> labels;
  std::vector<std::string> via_points;
  std::string request_id;
  bool detach = false;
  int progress_every = 0;
  std::string progress_interval;
  std::string output;
  std::string output_format;
};

google::protobuf::Duration ToDuration(double seconds) {
  google::protobuf::Duration duration;
  duration.set_seconds(static_cast<int64_t>(seconds));
  duration.set_nanos(
      static_cast<int32_t>((seconds - static_cast<double>(duration.seconds())) * 1e9));
  return duration;
}

// The planner's schema, to type --param values; nullopt-like empty algorithm when unavailable
// (the server then judges the values).
v1::Algorithm FetchSchema(const Connection& connection, const std::string& id) {
  auto stub = v1::AlgorithmService::NewStub(connection.channel());
  v1::GetAlgorithmRequest request;
  request.set_id(id);
  v1::Algorithm algorithm;
  if (!stub->GetAlgorithm(connection.UnaryContext().get(), request, &algorithm).ok()) return {};
  return algorithm;
}

absl::StatusOr<v1::PlanRequest> BuildRequest(const PlanOptions& options, const std::string& map_id,
                                             const v1::Algorithm& schema) {
  v1::PlanRequest request;
  request.set_map_id(map_id);
  absl::StatusOr<v1::Point> start = ParsePoint("--start", options.start);
  if (!start.ok()) return start.status();
  absl::StatusOr<v1::Point> goal = ParsePoint("--goal", options.goal);
  if (!goal.ok()) return goal.status();
  *request.mutable_start() = *start;
  *request.mutable_goal() = *goal;
  for (const std::string& text : options.via_points) {
    absl::StatusOr<v1::Point> via = ParsePoint("--via", text);
    if (!via.ok()) return via.status();
    *request.add_via_points() = *via;
  }
  request.set_algorithm(options.algorithm);
  for (const std::string& text : options.params) {
    absl::StatusOr<std::pair<std::string, std::string>> pair = ParseKeyValue("--param", text);
    if (!pair.ok()) return pair.status();
    const v1::ParameterSpec* spec = nullptr;
    for (const v1::ParameterSpec& candidate : schema.parameters()) {
      if (candidate.name() == pair->first) spec = &candidate;
    }
    absl::StatusOr<v1::ParamValue> value = ParseParamValue(pair->first, pair->second, spec);
    if (!value.ok()) return value.status();
    (*request.mutable_parameters())[pair->first] = *value;
  }
  request.set_seed(options.seed);
  request.set_clearance(options.clearance);
  if (options.preferred_clearance > 0) {
    request.mutable_preferences()->set_preferred_clearance(options.preferred_clearance);
  }
  if (options.turning_radius > 0) {
    request.mutable_preferences()->set_turning_radius(options.turning_radius);
  }
  if (options.max_speed > 0 || options.max_acceleration > 0 || options.max_yaw_rate > 0) {
    request.mutable_vehicle()->set_max_speed(options.max_speed);
    request.mutable_vehicle()->set_max_acceleration(options.max_acceleration);
    request.mutable_vehicle()->set_max_yaw_rate(options.max_yaw_rate);
  }
  request.set_alternatives(options.alternatives);
  request.mutable_limits()->set_max_iterations(options.max_iterations);
  if (!options.time_budget.empty()) {
    absl::StatusOr<double> seconds = ParseSeconds("--time-budget", options.time_budget);
    if (!seconds.ok()) return seconds.status();
    *request.mutable_limits()->mutable_time_budget() = ToDuration(*seconds);
  }
  request.set_smoothing(options.smoothing);
  request.mutable_progress()->set_every_iterations(options.progress_every);
  if (!options.progress_interval.empty()) {
    absl::StatusOr<double> seconds = ParseSeconds("--progress-interval", options.progress_interval);
    if (!seconds.ok()) return seconds.status();
    *request.mutable_progress()->mutable_min_interval() = ToDuration(*seconds);
  }
  for (const std::string& text : options.labels) {
    absl::StatusOr<std::pair<std::string, std::string>> pair = ParseKeyValue("--label", text);
    if (!pair.ok()) return pair.status();
    (*request.mutable_labels())[pair->first] = pair->second;
  }
  request.set_client_request_id(options.request_id);
  request.set_detached(options.detach);
  return request;
}

int Run(const GlobalOptions& global, PlanOptions options) {
  if (!options.output.empty()) {
    absl::StatusOr<std::string> format = PathFormatFor(options.output, options.output_format);
    if (!format.ok()) return ReportLocalError(global, format.status());
  }
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  if (options.progress_interval.empty() && options.progress_every == 0) {
    options.progress_interval = global.json ? "1s" : "100ms";
  }
  absl::StatusOr<v1::GetMapRequest> map = ParseMapReference("map", options.map);
  if (!map.ok()) return ReportLocalError(global, map.status());
  std::string map_id;
  if (grpc::Status status = ResolveMapId(*connection, *map, &map_id); !status.ok()) {
    return ReportRpcError(global, absl::StrCat("plan: map ", options.map), status);
  }
  const v1::Algorithm schema = FetchSchema(*connection, options.algorithm);
  absl::StatusOr<v1::PlanRequest> request = BuildRequest(options, map_id, schema);
  if (!request.ok()) return ReportLocalError(global, request.status());

  auto stub = v1::JobService::NewStub(connection->channel());
  if (options.detach) {
    v1::SubmitPlanResponse response;
    grpc::Status status = stub->SubmitPlan(connection->UnaryContext().get(), *request, &response);
    if (!status.ok()) return ReportRpcError(global, "plan", status);
    if (global.json) {
      PrintJson(response);
    } else {
      std::cout << (response.deduplicated() ? "job already submitted: " : "submitted job ")
                << response.job().id() << "\nfollow it with: swarmplan jobs watch "
                << response.job().id() << "\n";
    }
    return kExitOk;
  }
  FollowOptions follow;
  follow.action = "plan";
  follow.expected_iterations = ExpectedIterations(*connection, *request);
  follow.time_budget_seconds = DurationSeconds(request->limits().time_budget());
  follow.output_file = options.output;
  follow.output_format = options.output_format;
  std::unique_ptr<grpc::ClientContext> context = connection->StreamContext();
  std::unique_ptr<grpc::ClientReader<v1::JobEvent>> reader = stub->Plan(context.get(), *request);
  return FollowJobEvents(global, *connection, *reader, follow);
}

}  // namespace

void AddPlanCommand(CLI::App& app, const GlobalOptions& global, Action* action) {
  auto options = std::make_shared<PlanOptions>();
  CLI::App* command = app.add_subcommand(
      "plan",
      "Plan a path on a stored map, streaming progress; ends with a summary table.\n"
      "Coordinates: world units on every map kind (grid cell (x, y) covers [x, x+1) x\n"
      "[y, y+1) at resolution 1; on terrain x, y in the cell size's unit, the centre of\n"
      "cell (i, j) at origin + (i + 1/2, j + 1/2) * cellsize, and z a height).");
  command
      ->add_option("map", options->map,
                   "Map id, or NAME@VERSION (VERSION a number or 'latest'; see: swarmplan maps "
                   "list)")
      ->required();
  command->add_option("--start", options->start, "Start point x,y or x,y,z")->required();
  command->add_option("--goal", options->goal, "Goal point x,y or x,y,z")->required();
  command
      ->add_option("-a,--algorithm", options->algorithm, "Planner id (see: swarmplan algorithms)")
      ->capture_default_str();
  command
      ->add_option("-p,--param", options->params,
                   "Planner parameter NAME=VALUE (repeatable; see: swarmplan algorithms ID)")
      ->allow_extra_args(false);
  command->add_option("--seed", options->seed, "Random seed; 0: the server picks one");
  command->add_option("--clearance", options->clearance, "Distance to keep from obstacles")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--via", options->via_points,
                   "A point X,Y[,Z] the path passes through, in order (repeatable; at most 32)")
      ->allow_extra_args(false);
  command
      ->add_option("--preferred-clearance", options->preferred_clearance,
                   "Distance the path keeps from obstacles where it can (fleet objective of the "
                   "seeded swarm planners); 0: none")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--turning-radius", options->turning_radius,
                   "Smallest turning radius of the robot (fleet objective); 0: none")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--max-speed", options->max_speed,
                   "The vehicle's top speed (map units/s): the result carries the path timed "
                   "for it; 0: not timed")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--max-acceleration", options->max_acceleration,
                   "The vehicle's largest acceleration along and across the path (map "
                   "units/s^2); required with --max-speed")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--max-yaw-rate", options->max_yaw_rate,
                   "The vehicle's largest yaw rate (rad/s); 0: no limit")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--alternatives", options->alternatives,
                   "Up to K paths in distinct corridors, the result's included (seeded swarm "
                   "planners); 0: the result alone")
      ->check(CLI::Range(0, 8));
  command
      ->add_option("--max-iterations", options->max_iterations,
                   "Iteration cap; 0: the planner's default")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--time-budget", options->time_budget,
                      "Planning time limit, e.g. 30s, 500ms, 2m");
  command->add_option("--smoothing", options->smoothing,
                      "Smoothing of the raw path: none (default) or a method the server lists");
  command->add_option("--label", options->labels, "Label k=v stored with the job (repeatable)")
      ->allow_extra_args(false);
  command->add_option("--request-id", options->request_id,
                      "Idempotency key: resubmitting with it returns the first job");
  command->add_flag("--detach", options->detach,
                    "Submit and return at once with the job id (follow with: jobs watch)");
  command->add_option("--progress-every", options->progress_every,
                      "Report progress every N iterations (default: by time)");
  command->add_option("--progress-interval", options->progress_interval,
                      "At most one progress report per interval (default 100ms; 1s with --json)");
  command->add_option("-o,--output", options->output,
                      "Write the path to FILE (.json, .csv or .geojson)");
  command
      ->add_option("--output-format", options->output_format,
                   "Format of --output; vda5050: a VDA 5050 order (robot from the job's labels "
                   "manufacturer and serial_number)")
      ->check(CLI::IsMember(PathFormats()));
  OnChosen(command, action, [&global, options] { return Run(global, *options); });
}

}  // namespace swarmplan::client
