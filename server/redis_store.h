#pragma once

#include <memory>
#include <string>

#include "server/redis_client.h"
#include "server/store.h"

namespace swarmplan::server {

// The shared store: maps and jobs in one Redis database, so every replica pointed at it sees the
// same maps and job records. Each write is one script, so Redis applies it whole or not at all;
// how much an acknowledged write can lose when Redis itself crashes is Redis's appendfsync
// setting (deploy/README.md). Keys, all under `prefix`:
//   map:ID           hash: name, format, content_hash, source, created_us, info, version
//   maps             sorted set, every map as "CREATED_US(20 digits):ID" (lexicographic order
//                    is creation order, then id)
//   mapversions:NAME sorted set, the ids of the maps named NAME scored by version
//   mapnames         hash: the highest version each name ever had
//   job:ID           hash: state, record, created_us, finished_us (when finished),
//                    client_request_id
//   jobs             sorted set, every job as "CREATED_US(20 digits):ID" (lexicographic order
//                    is creation order, then id)
//   jobs:state:N     the same, per state
//   jobs:unfinished  the same, jobs without finished_us
//   jobs:finished    sorted set, id scored by finished_us
//   crid:REQUEST_ID  the same as jobs, per client_request_id
class RedisStore final : public Store {
 public:
  // Connects and checks the server answers (and accepts the password).
  static absl::StatusOr<std::unique_ptr<RedisStore>> Open(const RedisEndpoint& endpoint,
                                                          std::string prefix = "swarmplan:");

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

  RedisClient& client() { return *client_; }
  const std::string& prefix() const { return prefix_; }

 private:
  RedisStore(std::unique_ptr<RedisClient> client, std::string prefix)
      : client_(std::move(client)), prefix_(std::move(prefix)) {}
  // The maps with these ids that still exist, in the order given, with their sources or not.
  absl::StatusOr<std::vector<StoredMap>> GetMaps(const std::vector<std::string>& ids,
                                                 bool with_source);
  // The jobs with these ids that still exist, in the order given.
  absl::StatusOr<std::vector<StoredJob>> GetJobs(const std::vector<std::string>& ids);
  // Up to `limit` ids of the sorted set `key` (members "CREATED_US:ID"), newest first, before
  // `before` when given.
  absl::StatusOr<std::vector<std::string>> NewestMembers(const std::string& key,
                                                         const JobCursor* before, int limit);
  // Deletes those of `ids` that are still finished; returns them.
  absl::StatusOr<std::vector<std::string>> DeleteFinished(const std::vector<std::string>& ids);

  std::unique_ptr<RedisClient> client_;
  const std::string prefix_;
};

}  // namespace swarmplan::server
