#pragma once

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/time/time.h"

namespace swarmplan::server {

// A map as uploaded: the serialized swarmplan.v1.MapSource (format + file bytes, or structured
// data), so the server re-parses it at start.
struct StoredMap {
  std::string id;
  std::string name;
  std::string format;
  std::string content_hash;
  std::string source;  // serialized swarmplan.v1.MapSource
  absl::Time created_at;
};

// A job record: the serialized swarmplan.v1.Job (request, seed, state, timestamps, result).
struct StoredJob {
  std::string id;
  int state = 0;  // swarmplan.v1.JobState
  std::string record;
  absl::Time created_at;
  absl::Time finished_at = absl::InfiniteFuture();  // InfiniteFuture while unfinished
  std::string client_request_id;                    // the request's, "" when it has none
  // False for a job recorded before the store kept client_request_id beside the record.
  bool client_request_id_known = true;
};

// Where a job listing continues: before the job created at `created_us` with `id`.
struct JobCursor {
  int64_t created_us = 0;
  std::string id;
};

// Durable storage of maps and jobs. A write that returned OK survives a crash of the process.
// Thread-safe. The embedded implementation is SQLite (sqlite_store.h), the shared one Redis
// (redis_store.h); store_url.h opens the one --store names.
class Store {
 public:
  virtual ~Store() = default;

  virtual absl::Status PutMap(const StoredMap& map) = 0;
  // NOT_FOUND when absent.
  virtual absl::StatusOr<StoredMap> GetMap(const std::string& id) = 0;
  // Every map, oldest first.
  virtual absl::StatusOr<std::vector<StoredMap>> LoadMaps() = 0;
  // NOT_FOUND when absent.
  virtual absl::Status DeleteMap(const std::string& id) = 0;

  // Inserts or replaces the job with this id.
  virtual absl::Status PutJob(const StoredJob& job) = 0;
  // NOT_FOUND when absent.
  virtual absl::StatusOr<StoredJob> GetJob(const std::string& id) = 0;
  // The newest job with this client_request_id; NOT_FOUND when there is none.
  virtual absl::StatusOr<StoredJob> FindJobByClientRequestId(const std::string& id) = 0;
  // What a start has to look at, oldest first: unfinished jobs, and jobs whose
  // client_request_id is not known yet (client_request_id_known false).
  virtual absl::StatusOr<std::vector<StoredJob>> LoadJobsToRecover() = 0;
  // Up to `limit` jobs, newest first (created_us, then id, descending), before `before` when
  // given, of the given states (every state when empty).
  virtual absl::StatusOr<std::vector<StoredJob>> ListJobs(const JobCursor* before,
                                                          const std::vector<int>& states,
                                                          int limit) = 0;
  virtual absl::StatusOr<int64_t> CountFinishedJobs() = 0;
  // Deletes jobs that finished before `cutoff`; returns their ids.
  virtual absl::StatusOr<std::vector<std::string>> DeleteJobsFinishedBefore(absl::Time cutoff) = 0;
  // Deletes the `n` finished jobs that finished first; returns their ids.
  virtual absl::StatusOr<std::vector<std::string>> DeleteOldestFinishedJobs(int64_t n) = 0;
};

}  // namespace swarmplan::server
