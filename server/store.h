#pragma once

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/time/time.h"

namespace swarmplan::server {

// A map as uploaded: the serialized swarmplan.v1.MapSource (format + file bytes, or structured
// data), which a server parses when it first plans on the map, and its description.
struct StoredMap {
  std::string id;
  std::string name;
  std::string format;
  std::string content_hash;
  std::string source;  // serialized swarmplan.v1.MapSource; "" from GetMapInfo and ListMaps
  absl::Time created_at;
  // Serialized swarmplan.v1.MapInfo of the parsed map; "" for a map stored before the store kept
  // it (MapCatalog::Load fills it in).
  std::string info;
  // The map's version among the maps named `name`; 0 for a map stored before maps had versions
  // (MapCatalog::Load numbers them).
  int64_t version = 0;
};

// Where a map listing continues: after the map created at `created_us` with `id`.
struct MapCursor {
  int64_t created_us = 0;
  std::string id;
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

// FindMapVersion's NOT_FOUND.
inline absl::Status NoSuchMapVersion(const std::string& name, int64_t version) {
  return absl::NotFoundError(version > 0 ? absl::StrCat("map '", name, "' has no version ", version)
                                         : absl::StrCat("no map named '", name, "'"));
}

// Durable storage of maps and jobs. A write that returned OK survives a crash of the process.
// Thread-safe. The embedded implementation is SQLite (sqlite_store.h), the shared one Redis
// (redis_store.h); store_url.h opens the one --store names.
class Store {
 public:
  virtual ~Store() = default;

  // Inserts or replaces the map with this id and returns its version. A map put with version 0
  // keeps the version it is stored with, or, when it has none, gets the next version of its name
  // (one more than any map of that name ever had), atomically also across processes sharing the
  // store.
  virtual absl::StatusOr<int64_t> PutMap(const StoredMap& map) = 0;
  // NOT_FOUND when absent.
  virtual absl::StatusOr<StoredMap> GetMap(const std::string& id) = 0;
  // The map without its source; NOT_FOUND when absent.
  virtual absl::StatusOr<StoredMap> GetMapInfo(const std::string& id) = 0;
  // Up to `limit` maps without their sources, oldest first (created_us, then id), after `after`
  // when given.
  virtual absl::StatusOr<std::vector<StoredMap>> ListMaps(const MapCursor* after, int limit) = 0;
  // The map with this name and version (0: the highest stored), without its source; NOT_FOUND
  // when none.
  virtual absl::StatusOr<StoredMap> FindMapVersion(const std::string& name, int64_t version) = 0;
  // Up to `limit` maps named `name` without their sources, by version, after `after_version`.
  virtual absl::StatusOr<std::vector<StoredMap>> ListMapVersions(const std::string& name,
                                                                 int64_t after_version,
                                                                 int limit) = 0;
  virtual absl::StatusOr<int64_t> CountMaps() = 0;
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
