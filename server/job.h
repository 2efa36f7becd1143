#pragma once

#include <memory>
#include <optional>
#include <string>

#include "absl/base/thread_annotations.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "core/run.h"
#include "core/stop_token.h"
#include "server/job_events.h"
#include "server/shared_job_queue.h"
#include "server/store.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::server {

// Why a job was asked to stop early. kLeaseLost: another replica took the job's attempt over
// (the shared queue); this one stops and records nothing.
enum class CancelCause { kNone, kClient, kShutdown, kLeaseLost };

// One planning job while the server holds it: the resolved request, its stop token, its event
// buffer and its record (state, times, progress, result) as clients see it.
struct Job {
  Job(std::string job_id, bool is_detached)
      : id(job_id), detached(is_detached), events(std::move(job_id)) {}

  const std::string id;
  const bool detached;  // keeps running when its Plan caller goes away
  PlanRequest plan;     // core request: map resolved, seed fixed
  StopToken stop;
  JobEvents events;

  absl::Mutex mu;
  v1::Job record ABSL_GUARDED_BY(mu);
  CancelCause cancel_cause ABSL_GUARDED_BY(mu) = CancelCause::kNone;
  bool owner_gone ABSL_GUARDED_BY(mu) = false;  // the Plan call that submitted it has ended
  absl::Time queued_at ABSL_GUARDED_BY(mu);

  // With the shared queue of a redis:// store (job_manager_shared.cc):
  // the attempt this replica runs, while it holds it;
  std::optional<JobLease> lease ABSL_GUARDED_BY(mu);
  // the last entry of the job's shared event stream this replica wrote or applied;
  std::string shared_cursor ABSL_GUARDED_BY(mu) = "0";
  // the newest progress not shared yet (progress is shared at a bounded rate), and when
  // progress was last shared.
  EventPtr unshared_progress ABSL_GUARDED_BY(mu);
  absl::Time progress_shared_at ABSL_GUARDED_BY(mu) = absl::InfinitePast();
};

using JobPtr = std::shared_ptr<Job>;

bool IsFinal(v1::JobState state);
// The event that ends the stream of a job with this final record.
v1::JobEvent FinishedEvent(const v1::Job& record);
// The store's row of job `id` with `record`.
StoredJob ToStored(const std::string& id, const v1::Job& record);
// "succeeded", "no_path_found", ... (metric label values and logs).
std::string StateLabel(v1::JobState state);

}  // namespace swarmplan::server
