#pragma once

#include <atomic>
#include <list>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "core/registry.h"
#include "server/config.h"
#include "server/job.h"
#include "server/job_queue.h"
#include "server/map_catalog.h"
#include "server/metrics.h"
#include "server/optimum_cache.h"
#include "server/page_token.h"
#include "server/shared_job_events.h"
#include "server/shared_job_queue.h"
#include "server/store.h"

namespace swarmplan::server {

// The queue and the event streams that the replicas on one Redis share (a redis:// store).
struct SharedJobs {
  std::unique_ptr<SharedJobQueue> queue;
  std::unique_ptr<SharedJobEvents> events;
};

// Owns every job: validates and queues requests, runs them on the worker pool, records every
// state change in the store, publishes events, cancels, recovers after a restart and drains on
// shutdown. The gRPC services are thin adapters over it. Thread-safe.
//
// With SharedJobs (job_manager_shared.cc), jobs are queued in the shared queue instead: a
// feeder takes one whenever a local worker is free (a job submitted on any replica), a keeper
// renews the leases of the jobs running here and stops those cancelled elsewhere, and a relay
// follows the events of unfinished jobs this replica holds but another one runs.
class JobManager {
 public:
  JobManager(const ServerConfig& config, const Registry& registry, MapCatalog& maps, Store& store,
             Metrics& metrics, SharedJobs shared_jobs = {});
  ~JobManager();

  // Queues the stored queued and running jobs again with their recorded seed; finished ones
  // stay in the store (read when asked for) within the retention period and the cap.
  absl::Status Recover();

  struct Submitted {
    JobPtr job;
    bool deduplicated = false;
  };
  // Validates and queues. Errors: INVALID_ARGUMENT, NOT_FOUND, FAILED_PRECONDITION,
  // RESOURCE_EXHAUSTED (queue full), UNAVAILABLE (shutting down).
  absl::StatusOr<Submitted> Submit(const v1::PlanRequest& request, bool detached);

  // A job in memory (unfinished, or finished and cached), else a finished one read from the
  // store into the cache. NOT_FOUND when neither has it.
  absl::StatusOr<JobPtr> Find(const std::string& id);
  // The job as clients see it, with its live queue position.
  v1::Job Snapshot(Job& job, bool with_result) const;
  struct Page {
    std::vector<v1::Job> jobs;
    std::string next_page_token;  // empty on the last page
  };
  // Newest first (by creation time, then id), continuing after `page_token`: at most
  // `page_size` jobs and `max_bytes` serialized bytes (FitsPage). INVALID_ARGUMENT naming
  // page_token for a token List did not issue for these states.
  absl::StatusOr<Page> List(const std::vector<v1::JobState>& states, int page_size,
                            size_t max_bytes, const std::string& page_token);
  absl::StatusOr<v1::Job> Cancel(const std::string& id);

  // Deletes a map no queued or running job refers to: FAILED_PRECONDITION naming those jobs
  // otherwise, so that every job that may still run finds its map, also after a restart.
  absl::Status DeleteMap(const std::string& id);

  // A stream on `job` ended; `remaining` watchers are left. When the job's own Plan call ended
  // (`owner`) before the job finished, nobody watches and the job is not detached, it is
  // cancelled.
  void WatcherLeft(const JobPtr& job, bool owner, int remaining);

  // Refuses new jobs, lets running jobs finish within `grace`, then stops the rest and records
  // them as queued so the next start runs them again; the streams of every unfinished job get
  // a requeued event.
  void Shutdown(absl::Duration grace);

  int queue_depth() const { return queue_->depth(); }
  int busy_workers() const { return queue_->busy(); }
  // Finished jobs held in memory (at most --job-cache-entries).
  int cached_finished_jobs() const;

 private:
  absl::StatusOr<PlanRequest> Resolve(const v1::PlanRequest& request, uint64_t seed,
                                      v1::MapInfo* map_info) const;
  void Execute(const JobPtr& job);  // job_execution.cc
  // Sets the final state, records and publishes it; nothing when the job's lease was lost.
  void Finish(Job& job, v1::JobState state, const PlanResult* result, const std::string& reason)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // The job's record in a final state.
  static v1::Job FinalRecord(Job& job, v1::JobState state, const PlanResult* result,
                             const std::string& reason) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // Takes over a recorded final `record`: publishes it, counts it and retires the job.
  void Conclude(Job& job, v1::Job record) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // Records `record` as the job's state: through its lease when this replica runs it from the
  // shared queue, else in the store. false when nothing was recorded because another replica
  // took the attempt over (or Redis could not be reached); the lease is then given up.
  bool Persist(Job& job, const v1::Job& record) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // Records the job, queued again, for a later start or another replica; gives up its lease.
  void Requeue(Job& job) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // Publishes to the job's watchers here and, with SharedJobs, to its shared stream.
  void Announce(Job& job, v1::JobEvent event) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  void Add(const JobPtr& job);
  // A job built from its stored record; a finished one carries its finished event.
  static absl::StatusOr<JobPtr> FromStored(const StoredJob& stored);
  // From Finish: moves the job into the cache of finished jobs and deletes the oldest finished
  // jobs beyond --max-retained-jobs. Lock order: a job's mu, retention_mu_, mu_; nothing takes
  // a job's lock while holding mu_.
  void Retire(Job& job) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  void CacheFinished(const JobPtr& job) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void Forget(const std::vector<std::string>& ids) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  void EnforceRetainedCap();
  void SweepExpired(bool now = false);

  // job_manager_shared.cc
  bool shared() const { return shared_.queue != nullptr; }
  void StartShared();
  void StopFeeding();
  void StopShared();
  void FeedLoop();
  void KeepLoop();
  void RelayLoop();
  // Runs the job of a lease just taken from the shared queue on a local worker.
  void RunLeased(const JobLease& lease);
  // Appends to the job's shared stream; progress at a bounded rate.
  void ShareEvent(Job& job, const EventPtr& event) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  void AppendShared(Job& job, const v1::JobEvent& event) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // Another replica took the job's attempt over: stop it here and follow it instead.
  void LoseLease(Job& job) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  void Follow(const JobPtr& job);
  // An event of a followed job, read from its shared stream at `entry`.
  void ApplyFollowed(const JobPtr& job, const std::string& entry, const v1::JobEvent& event);
  // Brings followed jobs without recent events up to their stored records.
  void RefreshFollowedFromStore(const std::vector<JobPtr>& jobs);
  // Cancels a job that no worker here holds: takes it out of the shared queue, or asks the
  // replica running it to stop.
  absl::Status CancelShared(Job& job) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // A followed job's final record, read from the store or its stream.
  void ConcludeFollowed(Job& job, v1::Job record) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu);
  // The ids of unfinished jobs on map `id`, across replicas.
  absl::StatusOr<std::vector<std::string>> SharedJobsOnMap(const std::string& id);
  // Puts leased jobs that no worker started back into the shared queue.
  void ReleaseWaiting();

  const ServerConfig config_;
  const Registry& registry_;
  MapCatalog& maps_;
  Store& store_;
  Metrics& metrics_;
  OptimumCache optima_;

  // Serialises deleting finished jobs (the cap and the retention time); taken before mu_.
  absl::Mutex retention_mu_;
  int64_t finished_in_store_ ABSL_GUARDED_BY(retention_mu_) = 0;

  mutable absl::Mutex mu_;
  // Every unfinished job, and the finished ones in the cache. The store has every job; lists
  // and finished jobs outside the cache are read from it.
  std::map<std::string, JobPtr> jobs_ ABSL_GUARDED_BY(mu_);
  // Ids of the cached finished jobs, most recently used first, and where each one stands.
  std::list<std::string> cache_order_ ABSL_GUARDED_BY(mu_);
  std::map<std::string, std::list<std::string>::iterator> cache_pos_ ABSL_GUARDED_BY(mu_);
  absl::Time last_sweep_ ABSL_GUARDED_BY(mu_) = absl::InfinitePast();
  absl::Mutex submit_mu_;  // makes client_request_id dedupe atomic
  // Set by Shutdown: streams cut by the shutdown do not cancel their jobs, which stay queued.
  std::atomic<bool> shutting_down_{false};

  SharedJobs shared_;  // empty without a redis:// store
  // Jobs this replica runs from the shared queue, and unfinished jobs it holds that run elsewhere.
  std::map<std::string, JobPtr> leased_ ABSL_GUARDED_BY(mu_);
  std::map<std::string, JobPtr> followed_ ABSL_GUARDED_BY(mu_);
  std::atomic<bool> stop_feeding_{false};
  std::atomic<bool> stop_shared_{false};
  std::thread feeder_, keeper_, relay_;

  std::unique_ptr<JobQueue> queue_;  // last: its workers stop before the rest is destroyed
};

}  // namespace swarmplan::server
