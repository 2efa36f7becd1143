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
};

// Durable storage of maps and jobs. A write that returned OK survives a crash of the process.
// Thread-safe. The embedded implementation is SQLite (sqlite_store.h); a shared one (Redis) can
// implement the same interface.
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
  // Every job, oldest first.
  virtual absl::StatusOr<std::vector<StoredJob>> LoadJobs() = 0;
  // Deletes jobs that finished before `cutoff`; returns how many.
  virtual absl::StatusOr<int> DeleteJobsFinishedBefore(absl::Time cutoff) = 0;
};

}  // namespace swarmplan::server
