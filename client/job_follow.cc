#include "client/job_follow.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "client/exit_codes.h"
#include "client/output.h"
#include "client/path_files.h"
#include "swarmplan/v1/algorithms.grpc.pb.h"

namespace swarmplan::client {
namespace {

// Progress on stderr: a bar redrawn in place on a terminal, one line per event otherwise.
class ProgressDisplay {
 public:
  ProgressDisplay(bool enabled, int expected_iterations, double time_budget_seconds)
      : enabled_(enabled),
        tty_(isatty(fileno(stderr)) != 0),
        expected_iterations_(expected_iterations),
        time_budget_seconds_(time_budget_seconds) {}

  ~ProgressDisplay() { Close(); }

  void Show(const v1::JobEvent& event) {
    if (!enabled_) return;
    switch (event.event_case()) {
      case v1::JobEvent::kAccepted:
        Line(absl::StrCat("job ", event.job_id(), " accepted (queue position ",
                          event.accepted().queue_position(), ", seed ", event.accepted().seed(),
                          ")"));
        break;
      case v1::JobEvent::kStarted:
        Line(absl::StrCat("job ", event.job_id(), " started"));
        break;
      case v1::JobEvent::kProgress:
        Progress(event.progress());
        break;
      default:
        break;
    }
  }

  void Close() {
    if (bar_shown_) std::cerr << "\r\033[K" << std::flush;
    bar_shown_ = false;
  }

 private:
  void Line(const std::string& text) {
    Close();
    std::cerr << text << "\n" << std::flush;
  }

  void Progress(const v1::IterationStats& stats) {
    const int done = stats.iteration() + 1;
    const double elapsed = DurationSeconds(stats.elapsed());
    double eta = std::numeric_limits<double>::infinity();
    if (expected_iterations_ > 0 && done > 0) {
      eta = elapsed * std::max(0, expected_iterations_ - done) / done;
    }
    if (time_budget_seconds_ > 0)
      eta = std::min(eta, std::max(0.0, time_budget_seconds_ - elapsed));
    const std::string iteration = expected_iterations_ > 0
                                      ? absl::StrCat(done, "/", expected_iterations_)
                                      : absl::StrCat(done);
    const std::string text =
        absl::StrCat("iteration ", iteration, "  best ", FormatNumber(stats.best_fitness()),
                     stats.feasible() ? " (feasible)" : " (not feasible yet)", "  elapsed ",
                     FormatSeconds(elapsed), "  eta ", FormatSeconds(eta));
    if (!tty_) {
      std::cerr << text << "  mean " << FormatNumber(stats.mean_fitness()) << "  evaluations "
                << stats.evaluations() << "\n"
                << std::flush;
      return;
    }
    double fraction = 0.0;
    if (expected_iterations_ > 0) fraction = std::min(1.0, double(done) / expected_iterations_);
    if (time_budget_seconds_ > 0) {
      fraction = std::max(fraction, std::min(1.0, elapsed / time_budget_seconds_));
    }
    constexpr int kWidth = 24;
    const int filled = static_cast<int>(std::lround(fraction * kWidth));
    std::cerr << "\r\033[K[" << std::string(filled, '#') << std::string(kWidth - filled, '-')
              << "] " << absl::StrFormat("%3d%%", static_cast<int>(fraction * 100)) << "  " << text
              << std::flush;
    bar_shown_ = true;
  }

  bool enabled_;
  bool tty_;
  int expected_iterations_;
  double time_budget_seconds_;
  bool bar_shown_ = false;
};

// Whether the final path (the smoothed one, or the raw one when smoothing lost the clearance)
// turns no tighter than the requested radius, and its tightest turn.
std::string TurningRadiusNote(const v1::PlanResult& result, double radius) {
  const bool smoothed_final = result.smoothing_collision_free() && result.smoothed_path_size() > 0;
  const double curvature =
      (smoothed_final ? result.smoothed_metrics() : result.raw_metrics()).max_curvature();
  const std::string tightest =
      curvature > 0 ? absl::StrCat("tightest turn radius ", FormatNumber(1.0 / curvature))
                    : std::string("no turn");
  if (curvature <= (1.0 + 1e-6) / radius) {
    return absl::StrCat("kept (", tightest, ", asked ", FormatNumber(radius), ")");
  }
  return absl::StrCat("NOT kept: ", tightest, ", asked ", FormatNumber(radius),
                      " (no room to turn wider where the path bends, or a smoothing that does not "
                      "bound the curvature: use --smoothing bounded-curvature)");
}

void PrintResultTable(const v1::PlanResult& result) {
  Table table(
      {"PATH", "POINTS", "LENGTH", "MIN CLEARANCE", "MAX CURVATURE", "TURNS", "COLLISION-FREE"});
  auto add = [&](const std::string& name, int points, const v1::PathMetrics& metrics) {
    table.AddRow({name, absl::StrCat(points), FormatNumber(metrics.length()),
                  FormatNumber(metrics.min_clearance()), FormatNumber(metrics.max_curvature()),
                  absl::StrCat(metrics.turning_points()), metrics.collision_free() ? "yes" : "no"});
  };
  add("raw", result.raw_path_size(), result.raw_metrics());
  const bool smoothed = !result.smoothing().empty() && result.smoothing() != "none";
  if (smoothed && !result.smoothed_path().empty()) {
    add(absl::StrCat("smoothed (", result.smoothing(), ")"), result.smoothed_path_size(),
        result.smoothed_metrics());
  }
  for (int i = 0; i < result.alternatives_size(); ++i) {
    const v1::AlternativePath& alternative = result.alternatives(i);
    add(absl::StrCat("alternative ", i + 1, " (fitness ", FormatNumber(alternative.fitness()),
                     alternative.has_optimality_ratio()
                         ? absl::StrCat(", ratio ", FormatNumber(alternative.optimality_ratio()))
                         : std::string(),
                     ")"),
        alternative.path_size(), alternative.metrics());
  }
  table.Print(std::cout);
  if (!result.has_objective()) return;
  std::cout << "\n";
  Table objective({"OBJECTIVE", "TOTAL", "LENGTH", "CLEARANCE", "CURVATURE", "VIOLATION"});
  auto add_terms = [&](const std::string& name, const v1::ObjectiveTerms& t) {
    objective.AddRow({name, FormatNumber(t.total()), FormatNumber(t.length()),
                      FormatNumber(t.clearance()), FormatNumber(t.curvature()),
                      FormatNumber(t.violation())});
  };
  add_terms("path", result.objective());
  if (result.has_seed_objective()) add_terms("best seed", result.seed_objective());
  objective.Print(std::cout);
}

}  // namespace

void PrintJob(const v1::Job& job) {
  const v1::PlanRequest& request = job.request();
  const bool with_z = request.start().z() != 0.0 || request.goal().z() != 0.0;
  KeyValues rows = {
      {"job", job.id()},
      {"state", JobStateName(job.state())},
      {"algorithm", request.algorithm()},
      {"map", job.map_name().empty() ? request.map_id()
                                     : absl::StrCat(request.map_id(), " (", job.map_name(), "@",
                                                    job.map_version(), ")")},
      {"start", FormatPoint(request.start(), with_z)},
      {"goal", FormatPoint(request.goal(), with_z)},
      {"seed", absl::StrCat(job.seed())}};
  if (!request.labels().empty()) rows.push_back({"labels", FormatLabels(request.labels())});
  if (job.state() == v1::JOB_STATE_QUEUED) {
    rows.push_back({"queue position", absl::StrCat(job.queue_position())});
  }
  rows.push_back({"created", FormatTimestamp(job.created_at())});
  if (job.has_started_at()) rows.push_back({"started", FormatTimestamp(job.started_at())});
  if (job.has_finished_at()) rows.push_back({"finished", FormatTimestamp(job.finished_at())});
  if (job.state() == v1::JOB_STATE_RUNNING && job.has_progress()) {
    rows.push_back(
        {"progress", absl::StrCat("iteration ", job.progress().iteration() + 1, ", best ",
                                  FormatNumber(job.progress().best_fitness()))});
  }
  if (!job.failure_reason().empty()) rows.push_back({"failure", job.failure_reason()});
  if (job.has_result()) {
    const v1::PlanResult& result = job.result();
    rows.push_back({"found", result.found() ? "yes" : "no"});
    rows.push_back({"fitness", FormatNumber(result.fitness())});
    if (result.has_optimum_length()) {
      std::string optimum = absl::StrCat("length ", FormatNumber(result.optimum_length()));
      if (result.has_optimum_cost() && result.optimum_cost() != result.optimum_length()) {
        absl::StrAppend(&optimum, ", cost ", FormatNumber(result.optimum_cost()));
      }
      rows.push_back({"exact optimum", absl::StrCat(optimum, " (", result.optimum_planner(), ")")});
      if (result.has_optimality_ratio()) {
        rows.push_back(
            {"optimality ratio", absl::StrCat(absl::StrFormat("%.4f", result.optimality_ratio()),
                                              " (path over the exact optimum)")});
      }
    } else if (!result.optimum_note().empty()) {
      rows.push_back({"exact optimum", absl::StrCat("unknown: ", result.optimum_note())});
    }
    rows.push_back(
        {"iterations", absl::StrCat(result.iterations(), " (best at ", result.best_iteration(),
                                    "), ", result.evaluations(), " evaluations")});
    if (request.via_points_size() > 0) {
      std::string legs;
      for (int i = 0; i < result.legs_size(); ++i) {
        absl::StrAppend(&legs, i == 0 ? "" : ", ", FormatNumber(result.legs(i).metrics().length()),
                        result.legs(i).found() ? "" : " (no path)");
      }
      rows.push_back({"via points", absl::StrCat("reached ", result.via_points_reached(), " of ",
                                                 request.via_points_size(), "; legs ", legs)});
    }
    if (const double radius = request.preferences().turning_radius();
        radius > 0 && result.found()) {
      rows.push_back({"turning radius", TurningRadiusNote(result, radius)});
    }
    if (result.has_timed_path()) {
      const v1::VehicleLimits& vehicle = request.vehicle();
      rows.push_back(
          {"duration", absl::StrCat(FormatNumber(result.timed_path().duration()), " s at most ",
                                    FormatNumber(vehicle.max_speed()), " units/s, ",
                                    FormatNumber(vehicle.max_acceleration()), " units/s^2")});
    }
    rows.push_back({"stop reason", result.stop_reason()});
    rows.push_back({"time", absl::StrCat(FormatDuration(result.wall_time()), " wall, ",
                                         FormatDuration(result.cpu_time()), " cpu")});
  }
  PrintKeyValues(std::cout, rows);
  if (job.has_result()) {
    std::cout << "\n";
    PrintResultTable(job.result());
  }
}

int ExpectedIterations(const Connection& connection, const v1::PlanRequest& request) {
  int expected = request.limits().max_iterations();
  auto stub = v1::AlgorithmService::NewStub(connection.channel());
  v1::GetAlgorithmRequest get;
  get.set_id(request.algorithm());
  v1::Algorithm algorithm;
  if (!stub->GetAlgorithm(connection.UnaryContext().get(), get, &algorithm).ok()) return expected;
  for (const v1::ParameterSpec& spec : algorithm.parameters()) {
    if (spec.unit() != "iterations") continue;
    auto given = request.parameters().find(spec.name());
    const v1::ParamValue& value =
        given != request.parameters().end() ? given->second : spec.default_value();
    int64_t count = value.kind_case() == v1::ParamValue::kIntValue
                        ? value.int_value()
                        : static_cast<int64_t>(value.double_value());
    if (count > 0 && (expected <= 0 || count < expected)) expected = static_cast<int>(count);
    break;
  }
  return expected;
}

int WriteJobOutput(const GlobalOptions& global, const v1::Job& job, const std::string& file,
                   const std::string& format) {
  if (file.empty()) return kExitOk;
  absl::StatusOr<std::string> resolved = PathFormatFor(file, format);
  if (!resolved.ok()) return ReportLocalError(global, resolved.status());
  absl::Status written = WritePathFile(file, *resolved, job);
  if (!written.ok()) {
    // A job without a path already has its own exit code; say why no file was written.
    std::cerr << "swarmplan: " << written.message() << "\n";
    return written.code() == absl::StatusCode::kFailedPrecondition ? kExitNoPath : kExitUsage;
  }
  if (!global.json) std::cout << "path written to " << file << " (" << *resolved << ")\n";
  return kExitOk;
}

int FollowJobEvents(const GlobalOptions& global, const Connection& connection,
                    grpc::ClientReaderInterface<v1::JobEvent>& reader,
                    const FollowOptions& options) {
  ProgressDisplay display(!global.json, options.expected_iterations, options.time_budget_seconds);
  v1::JobEvent event;
  v1::Job job;  // built from the events, replaced by GetJob when it answers
  bool finished = false;
  while (reader.Read(&event)) {
    job.set_id(event.job_id());
    if (options.json_events)
      std::cout << ProtoToJson(event, /*pretty=*/false) << "\n" << std::flush;
    display.Show(event);
    if (event.has_accepted()) job.set_seed(event.accepted().seed());
    if (event.has_finished()) {
      finished = true;
      job.set_state(event.finished().state());
      if (event.finished().has_result()) *job.mutable_result() = event.finished().result();
      job.set_failure_reason(event.finished().failure_reason());
    }
  }
  display.Close();
  grpc::Status status = reader.Finish();
  if (!status.ok() && !finished) return ReportRpcError(global, options.action, status);
  if (!finished) {
    return ReportError(
        global, kExitOther,
        absl::StrCat(options.action, ": the stream ended before the job finished",
                     job.id().empty() ? "" : "; follow it with: swarmplan jobs watch ", job.id()));
  }
  // The finished event has the result; GetJob adds the request and the timestamps.
  auto stub = v1::JobService::NewStub(connection.channel());
  v1::GetJobRequest get;
  get.set_id(job.id());
  v1::Job fetched;
  if (stub->GetJob(connection.UnaryContext().get(), get, &fetched).ok() &&
      fetched.state() == job.state()) {
    if (!fetched.has_result() && job.has_result()) *fetched.mutable_result() = job.result();
    job = std::move(fetched);
  }
  if (global.json && !options.json_events) PrintJson(job);
  if (!global.json) {
    std::cout << "\n";
    PrintJob(job);
  }
  const int output_code = WriteJobOutput(global, job, options.output_file, options.output_format);
  const int state_code = ExitCodeForJobState(job.state());
  return state_code != kExitOk ? state_code : output_code;
}

}  // namespace swarmplan::client
