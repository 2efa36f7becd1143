// swarmplan jobs list|get|watch|cancel
#include <algorithm>
#include <iostream>
#include <memory>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/commands.h"
#include "client/exit_codes.h"
#include "client/job_follow.h"
#include "client/output.h"
#include "client/path_files.h"
#include "swarmplan/v1/jobs.grpc.pb.h"

namespace swarmplan::client {
namespace {

struct ListOptions {
  std::vector<std::string> states;
  int limit = 50;
};

struct JobOptions {
  std::string id;
  std::string output;
  std::string output_format;
};

int RunList(const GlobalOptions& global, const ListOptions& options) {
  v1::ListJobsRequest request;
  for (const std::string& name : options.states) {
    const v1::JobState state = ParseJobState(name);
    if (state == v1::JOB_STATE_UNSPECIFIED) {
      return ReportError(global, kExitUsage,
                         absl::StrCat("--state: unknown state '", name, "'; one of ",
                                      absl::StrJoin(JobStateNames(), ", ")));
    }
    request.add_states(state);
  }
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  auto stub = v1::JobService::NewStub(connection->channel());
  v1::ListJobsResponse all;
  request.set_page_size(options.limit > 0 ? std::min(options.limit, 1000) : 1000);
  do {
    v1::ListJobsResponse page;
    grpc::Status status = stub->ListJobs(connection->UnaryContext().get(), request, &page);
    if (!status.ok()) return ReportRpcError(global, "jobs list", status);
    for (auto& job : *page.mutable_jobs()) {
      if (options.limit > 0 && all.jobs_size() >= options.limit) break;
      *all.add_jobs() = std::move(job);
    }
    request.set_page_token(page.next_page_token());
    if (options.limit > 0 && all.jobs_size() >= options.limit) {
      all.set_next_page_token(page.next_page_token());
      break;
    }
  } while (!request.page_token().empty());
  if (global.json) {
    PrintJson(all);
    return kExitOk;
  }
  if (all.jobs().empty()) {
    std::cout << "no jobs\n";
    return kExitOk;
  }
  Table table({"ID", "STATE", "ALGORITHM", "MAP", "CREATED", "LABELS"});
  for (const v1::Job& job : all.jobs()) {
    table.AddRow({job.id(), JobStateName(job.state()), job.request().algorithm(),
                  job.request().map_id(), FormatTimestamp(job.created_at()),
                  FormatLabels(job.request().labels())});
  }
  table.Print(std::cout);
  if (!all.next_page_token().empty()) {
    std::cout << "(more jobs: raise --limit, or 0 for all)\n";
  }
  return kExitOk;
}

int RunGet(const GlobalOptions& global, const JobOptions& options) {
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  auto stub = v1::JobService::NewStub(connection->channel());
  v1::GetJobRequest request;
  request.set_id(options.id);
  v1::Job job;
  grpc::Status status = stub->GetJob(connection->UnaryContext().get(), request, &job);
  if (!status.ok()) return ReportRpcError(global, "jobs get", status);
  if (global.json) {
    PrintJson(job);
  } else {
    PrintJob(job);
  }
  return WriteJobOutput(global, job, options.output, options.output_format);
}

int RunWatch(const GlobalOptions& global, const JobOptions& options) {
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  auto stub = v1::JobService::NewStub(connection->channel());
  FollowOptions follow;
  follow.action = "jobs watch";
  follow.json_events = global.json;
  follow.output_file = options.output;
  follow.output_format = options.output_format;
  // The request tells how far the job will go, for the ETA.
  v1::GetJobRequest get;
  get.set_id(options.id);
  v1::Job job;
  grpc::Status status = stub->GetJob(connection->UnaryContext().get(), get, &job);
  if (!status.ok()) return ReportRpcError(global, "jobs watch", status);
  follow.expected_iterations = ExpectedIterations(*connection, job.request());
  follow.time_budget_seconds = DurationSeconds(job.request().limits().time_budget());
  v1::WatchJobRequest request;
  request.set_id(options.id);
  std::unique_ptr<grpc::ClientContext> context = connection->StreamContext();
  std::unique_ptr<grpc::ClientReader<v1::JobEvent>> reader = stub->WatchJob(context.get(), request);
  return FollowJobEvents(global, *connection, *reader, follow);
}

int RunCancel(const GlobalOptions& global, const std::string& id) {
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  auto stub = v1::JobService::NewStub(connection->channel());
  v1::CancelJobRequest request;
  request.set_id(id);
  v1::Job job;
  grpc::Status status = stub->CancelJob(connection->UnaryContext().get(), request, &job);
  if (!status.ok()) return ReportRpcError(global, "jobs cancel", status);
  if (global.json) {
    PrintJson(job);
  } else {
    std::cout << "job " << job.id() << ": " << JobStateName(job.state()) << "\n";
  }
  return kExitOk;
}

void AddOutputOptions(CLI::App* command, JobOptions* options) {
  command->add_option("-o,--output", options->output,
                      "Write the job's path to FILE (.json, .csv or .geojson)");
  command
      ->add_option("--output-format", options->output_format,
                   "Format of --output; vda5050: a VDA 5050 order (robot from the job's labels "
                   "manufacturer and serial_number)")
      ->check(CLI::IsMember(PathFormats()));
}

}  // namespace

void AddJobsCommand(CLI::App& app, const GlobalOptions& global, Action* action) {
  CLI::App* jobs = app.add_subcommand("jobs", "List, show, watch and cancel planning jobs");
  jobs->require_subcommand(1);

  auto list_options = std::make_shared<ListOptions>();
  CLI::App* list = jobs->add_subcommand("list", "List jobs, newest first");
  list->add_option("--state", list_options->states,
                   absl::StrCat("Only jobs in this state (repeatable): ",
                                absl::StrJoin(JobStateNames(), ", ")))
      ->allow_extra_args(false);
  list->add_option("--limit", list_options->limit, "At most this many jobs; 0: all")
      ->capture_default_str();
  OnChosen(list, action, [&global, list_options] { return RunList(global, *list_options); });

  auto get_options = std::make_shared<JobOptions>();
  CLI::App* get = jobs->add_subcommand("get", "Show a job and its result");
  get->add_option("id", get_options->id, "Job id")->required();
  AddOutputOptions(get, get_options.get());
  OnChosen(get, action, [&global, get_options] { return RunGet(global, *get_options); });

  auto watch_options = std::make_shared<JobOptions>();
  CLI::App* watch = jobs->add_subcommand(
      "watch", "Follow a job's progress until it finishes (closing never cancels it)");
  watch->add_option("id", watch_options->id, "Job id")->required();
  AddOutputOptions(watch, watch_options.get());
  OnChosen(watch, action, [&global, watch_options] { return RunWatch(global, *watch_options); });

  auto cancel_id = std::make_shared<std::string>();
  CLI::App* cancel = jobs->add_subcommand("cancel", "Cancel a queued or running job");
  cancel->add_option("id", *cancel_id, "Job id")->required();
  OnChosen(cancel, action, [&global, cancel_id] { return RunCancel(global, *cancel_id); });
}

}  // namespace swarmplan::client
