#pragma once

#include "core/registry.h"
#include "server/auth.h"
#include "server/config.h"
#include "server/job_manager.h"
#include "server/map_catalog.h"
#include "server/metrics.h"
#include "swarmplan/v1/algorithms.grpc.pb.h"
#include "swarmplan/v1/jobs.grpc.pb.h"
#include "swarmplan/v1/maps.grpc.pb.h"

namespace swarmplan::server {

// The gRPC services: thin adapters that check authentication, call the catalog or the job
// manager, and turn their absl::Status into grpc::Status (ToGrpcStatus).

class MapServiceImpl final : public v1::MapService::CallbackService {
 public:
  MapServiceImpl(MapCatalog& maps, JobManager& jobs, Metrics& metrics, const ServerConfig& config,
                 const Authenticator& auth)
      : maps_(maps), jobs_(jobs), metrics_(metrics), config_(config), auth_(auth) {}

  grpc::ServerUnaryReactor* UploadMap(grpc::CallbackServerContext* context,
                                      const v1::UploadMapRequest* request,
                                      v1::UploadMapResponse* response) override;
  grpc::ServerUnaryReactor* GetMap(grpc::CallbackServerContext* context,
                                   const v1::GetMapRequest* request,
                                   v1::GetMapResponse* response) override;
  grpc::ServerUnaryReactor* ListMaps(grpc::CallbackServerContext* context,
                                     const v1::ListMapsRequest* request,
                                     v1::ListMapsResponse* response) override;
  grpc::ServerUnaryReactor* DeleteMap(grpc::CallbackServerContext* context,
                                      const v1::DeleteMapRequest* request,
                                      v1::DeleteMapResponse* response) override;

 private:
  MapCatalog& maps_;
  JobManager& jobs_;
  Metrics& metrics_;
  const ServerConfig& config_;
  const Authenticator& auth_;
};

class AlgorithmServiceImpl final : public v1::AlgorithmService::CallbackService {
 public:
  AlgorithmServiceImpl(const Registry& registry, const Authenticator& auth)
      : registry_(registry), auth_(auth) {}

  grpc::ServerUnaryReactor* ListAlgorithms(grpc::CallbackServerContext* context,
                                           const v1::ListAlgorithmsRequest* request,
                                           v1::ListAlgorithmsResponse* response) override;
  grpc::ServerUnaryReactor* GetAlgorithm(grpc::CallbackServerContext* context,
                                         const v1::GetAlgorithmRequest* request,
                                         v1::Algorithm* response) override;

 private:
  const Registry& registry_;
  const Authenticator& auth_;
};

class JobServiceImpl final : public v1::JobService::CallbackService {
 public:
  JobServiceImpl(JobManager& jobs, const ServerConfig& config, const Authenticator& auth)
      : jobs_(jobs), config_(config), auth_(auth) {}

  grpc::ServerUnaryReactor* SubmitPlan(grpc::CallbackServerContext* context,
                                       const v1::PlanRequest* request,
                                       v1::SubmitPlanResponse* response) override;
  grpc::ServerWriteReactor<v1::JobEvent>* Plan(grpc::CallbackServerContext* context,
                                               const v1::PlanRequest* request) override;
  grpc::ServerWriteReactor<v1::JobEvent>* WatchJob(grpc::CallbackServerContext* context,
                                                   const v1::WatchJobRequest* request) override;
  grpc::ServerUnaryReactor* GetJob(grpc::CallbackServerContext* context,
                                   const v1::GetJobRequest* request, v1::Job* response) override;
  grpc::ServerUnaryReactor* ListJobs(grpc::CallbackServerContext* context,
                                     const v1::ListJobsRequest* request,
                                     v1::ListJobsResponse* response) override;
  grpc::ServerUnaryReactor* CancelJob(grpc::CallbackServerContext* context,
                                      const v1::CancelJobRequest* request,
                                      v1::Job* response) override;

 private:
  JobManager& jobs_;
  const ServerConfig& config_;
  const Authenticator& auth_;
};

// Page size as the API defines it: 0 -> 100, capped at 1000. INVALID_ARGUMENT when negative.
absl::StatusOr<int> ResolvePageSize(int page_size);
// The bytes a listing page may hold: --max-page-bytes, or half the message limit when smaller.
size_t PageByteBudget(const ServerConfig& config);

// Finishes a unary call with `status`.
grpc::ServerUnaryReactor* FinishUnary(grpc::CallbackServerContext* context,
                                      const grpc::Status& status);

}  // namespace swarmplan::server
