#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "server/redis_client.h"
#include "server/store.h"

namespace swarmplan::server {

// A job one replica has taken from the shared queue: the stream entry it holds and the attempt
// it runs. Attempts count from 1; each take, first or after a lease ran out, is a new attempt.
struct JobLease {
  std::string job_id;
  std::string entry;  // the stream entry id
  int64_t attempt = 0;
  bool reclaimed = false;  // taken over from a replica that stopped renewing its lease
};

// The queue that every replica on one Redis shares: a stream with one consumer group, each
// replica a consumer. A replica takes a job with XREADGROUP and holds it while it renews its
// lease (the entry's idle time); an entry idle longer than the lease is taken over by another
// replica (XAUTOCLAIM) as the job's next attempt. Every write of a taken job's record is
// conditional on the taker still holding that attempt, so however often a job runs, exactly one
// attempt records its result. A job's record and its place in the queue change together, in one
// script. Thread-safe. Keys, under `prefix` (beside those of RedisStore):
//   queue        stream of {job: ID}, consumer group `workers`
//   queued:ID    the entry id of the job's place in the queue
//   run:ID       hash: attempt (the last one begun), consumer and entry holding it
//   cancel:ID    set while a cancellation of the job waits to be seen by the replica running it
class SharedJobQueue {
 public:
  struct Options {
    std::string consumer;  // this replica's name in the group; unique among live replicas
    absl::Duration lease = absl::Seconds(10);
    int64_t capacity = 64;  // jobs waiting to be taken, cluster-wide
  };

  // Creates the stream and the group when they do not exist yet.
  static absl::StatusOr<std::unique_ptr<SharedJobQueue>> Open(RedisClient& client,
                                                              std::string prefix, Options options);

  // Records `job` and queues it, in one step. Returns how many jobs wait ahead of it;
  // RESOURCE_EXHAUSTED when `capacity` jobs already wait, unless `ignore_capacity`.
  absl::StatusOr<int64_t> Push(const StoredJob& job, bool ignore_capacity = false);

  // The next job for this replica: first one whose lease ran out, else one that waits, waiting
  // up to `wait` for one to arrive. nullopt when there is none. Entries of jobs that finished
  // meanwhile (cancelled, or recorded by an earlier attempt) are dropped on the way.
  absl::StatusOr<std::optional<JobLease>> Take(absl::Duration wait);

  // Extends the lease. false when this replica no longer holds the attempt (another took the
  // job over): it must stop the job and record nothing.
  absl::StatusOr<bool> Renew(const JobLease& lease);

  // Records a state of the job held by `lease`; a final state (finished_at set) also takes the
  // job out of the queue. false, and nothing written, when the attempt is no longer held.
  absl::StatusOr<bool> Record(const JobLease& lease, const StoredJob& job);

  // Puts the held job back at the end of the queue, recorded as `job` (queued): for a replica
  // that stops before the job finishes. false when the attempt is no longer held.
  absl::StatusOr<bool> Release(const JobLease& lease, const StoredJob& job);

  // Takes a job that no replica has taken yet out of the queue and records `job` (its final,
  // cancelled record), in one step. false when the job is not waiting (taken, or finished).
  absl::StatusOr<bool> RemoveWaiting(const StoredJob& job);

  // Asks the replica running `job_id` to stop it: a flag it reads (CancelRequested) and that
  // lives `ttl` at most.
  absl::Status RequestCancel(const std::string& job_id, absl::Duration ttl = absl::Hours(24));
  // For each id, whether a cancellation was requested.
  absl::StatusOr<std::vector<bool>> CancelRequested(const std::vector<std::string>& job_ids);

  // Jobs waiting to be taken, cluster-wide.
  absl::StatusOr<int64_t> Waiting();

  const Options& options() const { return options_; }

 private:
  SharedJobQueue(RedisClient& client, std::string prefix, Options options)
      : client_(client), prefix_(std::move(prefix)), options_(std::move(options)) {}
  // Begins the next attempt of the job of `entry`, just delivered to or claimed by this
  // replica; nullopt when the job finished meanwhile (its entry is dropped).
  absl::StatusOr<std::optional<JobLease>> Begin(const std::string& entry, const RedisReply& fields,
                                                bool reclaimed);
  std::vector<std::string> LeaseArgs(const JobLease& lease) const;

  RedisClient& client_;
  const std::string prefix_;
  const Options options_;
};

// A consumer name unique to this process: host name, process id and a random suffix.
std::string UniqueConsumerName();

}  // namespace swarmplan::server
