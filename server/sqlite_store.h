#pragma once

#include <memory>
#include <string>

#include "absl/base/thread_annotations.h"
#include "absl/synchronization/mutex.h"
#include "server/store.h"

struct sqlite3;

namespace swarmplan::server {

// The embedded store: one SQLite database (WAL mode, synchronous=FULL) in a data directory.
class SqliteStore final : public Store {
 public:
  // Creates the directory and the schema when needed.
  static absl::StatusOr<std::unique_ptr<SqliteStore>> Open(const std::string& data_dir);
  ~SqliteStore() override;

  absl::StatusOr<int64_t> PutMap(const StoredMap& map) override;
  absl::StatusOr<StoredMap> GetMap(const std::string& id) override;
  absl::StatusOr<StoredMap> GetMapInfo(const std::string& id) override;
  absl::StatusOr<std::vector<StoredMap>> ListMaps(const MapCursor* after, int limit) override;
  absl::StatusOr<StoredMap> FindMapVersion(const std::string& name, int64_t version) override;
  absl::StatusOr<std::vector<StoredMap>> ListMapVersions(const std::string& name,
                                                         int64_t after_version, int limit) override;
  absl::StatusOr<int64_t> CountMaps() override;
  absl::Status DeleteMap(const std::string& id) override;
  absl::Status PutJob(const StoredJob& job) override;
  absl::StatusOr<StoredJob> GetJob(const std::string& id) override;
  absl::StatusOr<StoredJob> FindJobByClientRequestId(const std::string& id) override;
  absl::StatusOr<std::vector<StoredJob>> LoadJobsToRecover() override;
  absl::StatusOr<std::vector<StoredJob>> ListJobs(const JobCursor* before,
                                                  const std::vector<int>& states,
                                                  int limit) override;
  absl::StatusOr<int64_t> CountFinishedJobs() override;
  absl::StatusOr<std::vector<std::string>> DeleteJobsFinishedBefore(absl::Time cutoff) override;
  absl::StatusOr<std::vector<std::string>> DeleteOldestFinishedJobs(int64_t n) override;

 private:
  explicit SqliteStore(sqlite3* db) : db_(db) {}
  absl::Status Exec(const char* sql) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Adds columns and indexes a database made by an earlier version lacks.
  absl::Status Migrate() ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Adds `column` (with `type`) to `table` unless it has it.
  absl::Status AddColumn(const char* table, const char* column, const char* type)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  absl::StatusOr<int64_t> PutMapLocked(const StoredMap& map) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // The version `map` is to be stored with (see Store::PutMap).
  absl::StatusOr<int64_t> VersionFor(const StoredMap& map) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Runs `select` (ids of jobs to delete, bound by `bind`) and deletes those jobs.
  absl::StatusOr<std::vector<std::string>> DeleteSelected(const char* select, int64_t value)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);

  absl::Mutex mu_;
  sqlite3* db_ ABSL_GUARDED_BY(mu_);
};

}  // namespace swarmplan::server
