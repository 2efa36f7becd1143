#include "server/grpc_status.h"
#include "server/job_event_stream.h"
#include "server/request_validation.h"
#include "server/services.h"

namespace swarmplan::server {

grpc::ServerUnaryReactor* JobServiceImpl::SubmitPlan(grpc::CallbackServerContext* context,
                                                     const v1::PlanRequest* request,
                                                     v1::SubmitPlanResponse* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::StatusOr<JobManager::Submitted> submitted = jobs_.Submit(*request, /*detached=*/true);
  if (!submitted.ok()) return FinishUnary(context, ToGrpcStatus(submitted.status()));
  *response->mutable_job() = jobs_.Snapshot(*submitted->job, /*with_result=*/true);
  response->set_deduplicated(submitted->deduplicated);
  return FinishUnary(context, grpc::Status::OK);
}

grpc::ServerWriteReactor<v1::JobEvent>* JobServiceImpl::Plan(grpc::CallbackServerContext* context,
                                                             const v1::PlanRequest* request) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FailedJobEventStream(s);
  absl::StatusOr<JobManager::Submitted> submitted = jobs_.Submit(*request, request->detached());
  if (!submitted.ok()) return FailedJobEventStream(ToGrpcStatus(submitted.status()));
  JobPtr job = submitted->job;
  if (submitted->deduplicated) {
    const int64_t cursor = job->events.LatestStateCursor();
    return StreamJobEvents(jobs_, std::move(job), cursor, /*owner=*/false,
                           config_.max_watchers_per_job);
  }
  return StreamJobEvents(jobs_, std::move(job), 0, /*owner=*/true, config_.max_watchers_per_job);
}

grpc::ServerWriteReactor<v1::JobEvent>* JobServiceImpl::WatchJob(
    grpc::CallbackServerContext* context, const v1::WatchJobRequest* request) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FailedJobEventStream(s);
  absl::StatusOr<JobPtr> job = jobs_.Find(request->id());
  if (!job.ok()) return FailedJobEventStream(ToGrpcStatus(job.status()));
  const int64_t cursor = (*job)->events.LatestStateCursor();
  return StreamJobEvents(jobs_, std::move(*job), cursor, /*owner=*/false,
                         config_.max_watchers_per_job);
}

grpc::ServerUnaryReactor* JobServiceImpl::GetJob(grpc::CallbackServerContext* context,
                                                 const v1::GetJobRequest* request,
                                                 v1::Job* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::StatusOr<JobPtr> job = jobs_.Find(request->id());
  if (!job.ok()) return FinishUnary(context, ToGrpcStatus(job.status()));
  *response = jobs_.Snapshot(**job, /*with_result=*/true);
  return FinishUnary(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* JobServiceImpl::ListJobs(grpc::CallbackServerContext* context,
                                                   const v1::ListJobsRequest* request,
                                                   v1::ListJobsResponse* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::StatusOr<int> page_size = ResolvePageSize(request->page_size());
  if (!page_size.ok()) return FinishUnary(context, ToGrpcStatus(page_size.status()));
  if (absl::Status s = CheckStateFilter(request->states()); !s.ok()) {
    return FinishUnary(context, ToGrpcStatus(s));
  }
  std::vector<v1::JobState> states;
  for (int s : request->states()) states.push_back(static_cast<v1::JobState>(s));
  absl::StatusOr<JobManager::Page> page =
      jobs_.List(states, *page_size, PageByteBudget(config_), request->page_token());
  if (!page.ok()) return FinishUnary(context, ToGrpcStatus(page.status()));
  for (v1::Job& job : page->jobs) *response->add_jobs() = std::move(job);
  response->set_next_page_token(page->next_page_token);
  return FinishUnary(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* JobServiceImpl::CancelJob(grpc::CallbackServerContext* context,
                                                    const v1::CancelJobRequest* request,
                                                    v1::Job* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::StatusOr<v1::Job> job = jobs_.Cancel(request->id());
  if (!job.ok()) return FinishUnary(context, ToGrpcStatus(job.status()));
  *response = std::move(*job);
  return FinishUnary(context, grpc::Status::OK);
}

}  // namespace swarmplan::server
