#pragma once

#include <grpcpp/grpcpp.h>

#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "server/server.h"
#include "swarmplan/v1/jobs.grpc.pb.h"
#include "swarmplan/v1/maps.grpc.pb.h"

namespace swarmplan::bench {

// A swarmplan server running in-process on 127.0.0.1 (a port gRPC picks) with its data in a
// fresh temporary directory, removed at destruction (or in the store `store` names, when given),
// and a client channel to it.
class BenchServer {
 public:
  static absl::StatusOr<std::unique_ptr<BenchServer>> Start(int workers, int queue_capacity,
                                                            const std::string& store = "");
  ~BenchServer();

  v1::JobService::Stub& jobs() { return *jobs_; }

  // Uploads a map file; the format is guessed from its name. Returns the map's id.
  absl::StatusOr<std::string> UploadMapFile(const std::string& path);

  absl::StatusOr<v1::Job> Submit(const v1::PlanRequest& request);
  // A Plan stream read to its end; the finished event's result.
  absl::StatusOr<v1::PlanResult> Plan(const v1::PlanRequest& request, absl::Duration give_up);
  absl::StatusOr<v1::Job> GetJob(const std::string& id);
  // Polls GetJob every `poll` until the job is final; DEADLINE_EXCEEDED after `give_up`.
  absl::StatusOr<v1::Job> WaitUntilFinal(const std::string& id, absl::Duration poll,
                                         absl::Duration give_up);

 private:
  BenchServer() = default;

  std::string data_dir_;
  std::unique_ptr<server::Server> server_;
  std::shared_ptr<grpc::Channel> channel_;
  std::unique_ptr<v1::MapService::Stub> maps_;
  std::unique_ptr<v1::JobService::Stub> jobs_;
};

bool IsFinalJobState(v1::JobState state);

struct ThroughputResult;
// The time until `jobs` copies of `request`, submitted round-robin to `servers`, are all final
// (SUCCEEDED or NO_PATH_FOUND; anything else is an error). `workers` is left 0.
absl::StatusOr<ThroughputResult> TimeJobs(const std::vector<BenchServer*>& servers,
                                          const v1::PlanRequest& request, int jobs);

// A gRPC status as an absl::Status, prefixed with the call's name.
absl::Status FromGrpc(const std::string& call, const grpc::Status& status);

}  // namespace swarmplan::bench
