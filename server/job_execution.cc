// JobManager::Execute: what a worker does with one job.
#include <spdlog/spdlog.h>

#include <functional>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "core/via_points.h"
#include "server/job_manager.h"
#include "server/proto_convert.h"

namespace swarmplan::server {
namespace {

// Publishes a job's iterations at the rate its request asked for. Never blocks on watchers.
class ProgressPublisher final : public Observer {
 public:
  // `publish` is called with the job's lock held.
  ProgressPublisher(Job& job, int every_iterations, absl::Duration min_interval,
                    std::function<void(v1::JobEvent)> publish)
      : job_(job),
        every_(std::max(every_iterations, 1)),
        min_interval_(min_interval),
        publish_(std::move(publish)) {}

  void OnIteration(const IterationStats& stats) override {
    last_ = stats;
    seen_ = true;
    if (stats.iteration % every_ != 0 && stats.iteration != 0) return;
    const absl::Time now = absl::Now();
    if (published_ && now - last_publish_ < min_interval_) return;
    Publish(stats, now);
  }

  // The last iteration is always reported.
  void Flush() {
    if (seen_ && (!published_ || last_published_iteration_ != last_.iteration)) {
      Publish(last_, absl::Now());
    }
  }

 private:
  void Publish(const IterationStats& stats, absl::Time now) {
    published_ = true;
    last_publish_ = now;
    last_published_iteration_ = stats.iteration;
    v1::JobEvent event;
    *event.mutable_progress() = ToProto(stats);
    absl::MutexLock lock(&job_.mu);
    *job_.record.mutable_progress() = event.progress();
    publish_(std::move(event));
  }

  Job& job_;
  const int every_;
  const absl::Duration min_interval_;
  const std::function<void(v1::JobEvent)> publish_;
  IterationStats last_;
  bool seen_ = false;
  bool published_ = false;
  absl::Time last_publish_;
  int last_published_iteration_ = -1;
};

v1::JobState FinalState(const PlanResult& result, CancelCause cause) {
  if (cause != CancelCause::kNone || result.stop_reason == StopReason::kCancelled) {
    return v1::JOB_STATE_CANCELLED;
  }
  if (result.found) return v1::JOB_STATE_SUCCEEDED;
  if (result.stop_reason == StopReason::kDeadline) return v1::JOB_STATE_DEADLINE_EXCEEDED;
  return v1::JOB_STATE_NO_PATH_FOUND;
}

}  // namespace

void JobManager::Execute(const JobPtr& job) {
  // With the shared queue, the attempt this run belongs to: a later attempt taken here after
  // this one was lost is not this run's to record.
  int64_t attempt = 0;
  {
    absl::MutexLock lock(&job->mu);
    if (IsFinal(job->record.state()) || job->cancel_cause == CancelCause::kLeaseLost) return;
    if (job->lease.has_value()) attempt = job->lease->attempt;
    const absl::Time now = absl::Now();
    v1::Job running = job->record;
    running.set_state(v1::JOB_STATE_RUNNING);
    running.clear_queue_position();
    *running.mutable_started_at() = ToProto(now);
    if (!Persist(*job, running)) return;
    job->record = std::move(running);
    Announce(*job, [] {
      v1::JobEvent started;
      started.mutable_started();
      return started;
    }());
    metrics_.JobStarted(job->plan.algorithm, absl::ToDoubleSeconds(now - job->queued_at));
    spdlog::info("job {} running algorithm={} map={} queue_wait={:.3f}s", job->id,
                 job->plan.algorithm, job->record.request().map_id(),
                 absl::ToDoubleSeconds(now - job->queued_at));
  }

  const v1::ProgressOptions& progress = job->record.request().progress();
  ProgressPublisher publisher(*job, progress.every_iterations(), FromProto(progress.min_interval()),
                              [this, &job](v1::JobEvent event) ABSL_NO_THREAD_SAFETY_ANALYSIS {
                                Announce(*job, std::move(event));
                              });
  absl::StatusOr<PlanResult> result = RunPlan(registry_, job->plan, job->stop, publisher);
  publisher.Flush();
  if (result.ok() && !job->stop.cancelled()) {
    std::vector<Optimum> legs;
    for (const Problem& leg : LegProblems(job->plan)) {
      legs.push_back(optima_.Get(job->record.request().map_id(), leg));
    }
    SetOptimum(*job->plan.problem.map, CombineLegOptima(legs), *result);
  }

  {
    absl::MutexLock lock(&job->mu);
    const int64_t holding = job->lease.has_value() ? job->lease->attempt : 0;
    if (job->cancel_cause == CancelCause::kLeaseLost || holding != attempt) {
      spdlog::info("job {} stopped here: another replica runs it now", job->id);
    } else if (job->cancel_cause == CancelCause::kShutdown) {
      // Not finished: recorded as queued so the next start (or another replica) runs it again.
      job->record.set_state(v1::JOB_STATE_QUEUED);
      job->record.clear_started_at();
      job->record.clear_progress();
      Requeue(*job);
      spdlog::info("job {} re-queued (shutdown) algorithm={} map={}", job->id, job->plan.algorithm,
                   job->record.request().map_id());
    } else if (!result.ok()) {
      Finish(*job, v1::JOB_STATE_FAILED, nullptr, std::string(result.status().message()));
    } else {
      Finish(*job, FinalState(*result, job->cancel_cause), &*result, "");
    }
  }
  SweepExpired();
}

}  // namespace swarmplan::server
