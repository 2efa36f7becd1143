#include "bench/service/bench_server.h"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "core/map/io/map_io.h"
#include "core/registry.h"

namespace swarmplan::bench {

absl::StatusOr<std::unique_ptr<BenchServer>> BenchServer::Start(int workers, int queue_capacity,
                                                                const std::string& store) {
  std::unique_ptr<BenchServer> bench(new BenchServer());
  std::string pattern =
      (std::filesystem::temp_directory_path() / "swarmplan-service-bench-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    return absl::InternalError(absl::StrCat("cannot create a temporary directory ", pattern));
  }
  bench->data_dir_ = pattern;

  server::ServerConfig config;
  config.listen = "127.0.0.1:0";
  config.data_dir = bench->data_dir_;
  config.store = store;
  config.metrics_port = 0;
  config.workers = workers;
  config.queue_capacity = queue_capacity;
  config.shutdown_grace = absl::Seconds(5);
  config.log_level = "warn";
  absl::StatusOr<std::unique_ptr<server::Server>> server =
      server::Server::Start(config, DefaultRegistry());
  if (!server.ok()) return server.status();
  bench->server_ = std::move(*server);
  bench->channel_ = grpc::CreateChannel("127.0.0.1:" + std::to_string(bench->server_->port()),
                                        grpc::InsecureChannelCredentials());
  if (!bench->channel_->WaitForConnected(std::chrono::system_clock::now() +
                                         std::chrono::seconds(20))) {
    return absl::UnavailableError("the in-process server did not accept a connection in 20 s");
  }
  bench->maps_ = v1::MapService::NewStub(bench->channel_);
  bench->jobs_ = v1::JobService::NewStub(bench->channel_);
  return bench;
}

BenchServer::~BenchServer() {
  jobs_.reset();
  maps_.reset();
  channel_.reset();
  if (server_ != nullptr) server_->Shutdown();
  server_.reset();
  std::error_code ec;
  std::filesystem::remove_all(data_dir_, ec);
}

absl::StatusOr<std::string> BenchServer::UploadMapFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return absl::NotFoundError(absl::StrCat("cannot read map file ", path));
  std::ostringstream content;
  content << file.rdbuf();
  const std::string name = std::filesystem::path(path).filename().string();

  v1::UploadMapRequest request;
  request.set_name(name);
  v1::MapFiles* files = request.mutable_source()->mutable_files();
  files->set_format(GuessMapFormat(path));
  v1::MapFile* map_file = files->add_files();
  map_file->set_name(name);
  map_file->set_content(content.str());
  v1::UploadMapResponse response;
  grpc::ClientContext context;
  if (grpc::Status status = maps_->UploadMap(&context, request, &response); !status.ok()) {
    return FromGrpc(absl::StrCat("UploadMap ", path), status);
  }
  return response.map().id();
}

absl::StatusOr<v1::Job> BenchServer::Submit(const v1::PlanRequest& request) {
  v1::SubmitPlanResponse response;
  grpc::ClientContext context;
  if (grpc::Status status = jobs_->SubmitPlan(&context, request, &response); !status.ok()) {
    return FromGrpc("SubmitPlan", status);
  }
  return response.job();
}

absl::StatusOr<v1::PlanResult> BenchServer::Plan(const v1::PlanRequest& request,
                                                 absl::Duration give_up) {
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + absl::ToChronoSeconds(give_up));
  std::unique_ptr<grpc::ClientReader<v1::JobEvent>> reader = jobs_->Plan(&context, request);
  v1::JobEvent event;
  v1::PlanResult result;
  bool finished = false;
  while (reader->Read(&event)) {
    if (event.has_finished()) {
      result = event.finished().result();
      finished = true;
    }
  }
  if (grpc::Status status = reader->Finish(); !status.ok()) return FromGrpc("Plan", status);
  if (!finished) return absl::InternalError("Plan stream ended without a finished event");
  return result;
}

absl::StatusOr<v1::Job> BenchServer::GetJob(const std::string& id) {
  v1::GetJobRequest request;
  request.set_id(id);
  v1::Job job;
  grpc::ClientContext context;
  if (grpc::Status status = jobs_->GetJob(&context, request, &job); !status.ok()) {
    return FromGrpc("GetJob", status);
  }
  return job;
}

absl::StatusOr<v1::Job> BenchServer::WaitUntilFinal(const std::string& id, absl::Duration poll,
                                                    absl::Duration give_up) {
  const absl::Time deadline = absl::Now() + give_up;
  while (true) {
    absl::StatusOr<v1::Job> job = GetJob(id);
    if (!job.ok() || IsFinalJobState(job->state())) return job;
    if (absl::Now() > deadline) {
      return absl::DeadlineExceededError(
          absl::StrCat("job ", id, " not finished after ", absl::FormatDuration(give_up)));
    }
    absl::SleepFor(poll);
  }
}

bool IsFinalJobState(v1::JobState state) {
  return state != v1::JOB_STATE_UNSPECIFIED && state != v1::JOB_STATE_QUEUED &&
         state != v1::JOB_STATE_RUNNING;
}

absl::Status FromGrpc(const std::string& call, const grpc::Status& status) {
  return absl::Status(static_cast<absl::StatusCode>(status.error_code()),
                      absl::StrCat(call, ": ", status.error_message()));
}

}  // namespace swarmplan::bench
