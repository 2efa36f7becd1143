#pragma once

#include <memory>
#include <string>

#include "absl/base/thread_annotations.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "core/run.h"
#include "core/stop_token.h"
#include "server/job_events.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::server {

// Why a job was asked to stop early.
enum class CancelCause { kNone, kClient, kShutdown };

// One planning job while the server holds it: the resolved request, its stop token, its event
// buffer and its record (state, times, progress, result) as clients see it.
struct Job {
  Job(std::string job_id, bool is_detached)
      : id(job_id), detached(is_detached), events(std::move(job_id)) {}

  const std::string id;
  const bool detached;  // keeps running when its Plan caller goes away
  PlanRequest plan;     // core request: map resolved, seed fixed
  std::string map_name;
  StopToken stop;
  JobEvents events;

  absl::Mutex mu;
  v1::Job record ABSL_GUARDED_BY(mu);
  CancelCause cancel_cause ABSL_GUARDED_BY(mu) = CancelCause::kNone;
  bool owner_gone ABSL_GUARDED_BY(mu) = false;  // the Plan call that submitted it has ended
  absl::Time queued_at ABSL_GUARDED_BY(mu);
};

using JobPtr = std::shared_ptr<Job>;

bool IsFinal(v1::JobState state);
// "succeeded", "no_path_found", ... (metric label values and logs).
std::string StateLabel(v1::JobState state);

}  // namespace swarmplan::server
