#include "server/redis_store.h"

#include <algorithm>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "server/redis_job_lua.h"

namespace swarmplan::server {
namespace {

// Every script takes the key prefix as ARGV[1].

// Removes a map from every index it is in (its hash says which) and deletes it; returns whether
// it existed.
constexpr const char* kUnindexMap = R"lua(
local function unindex_map(p, id)
  local key = p .. 'map:' .. id
  local old = redis.call('HMGET', key, 'created_us', 'content_hash', 'name')
  if not old[1] then return 0 end
  local member = old[1] .. ':' .. id
  redis.call('ZREM', p .. 'maps', member)
  redis.call('ZREM', p .. 'mapversions:' .. old[3], id)
  -- the content index that stores kept before maps had versions
  redis.call('ZREM', p .. 'mapkey:' .. old[2] .. ':' .. old[3], member)
  return redis.call('DEL', key)
end
)lua";

// ARGV: prefix, id, name, format, content_hash, source, created_us (20 digits), info, version
// (0: the stored one, else the name's next). Returns the version.
const std::string& PutMapScript() {
  static const auto* script = new std::string(absl::StrCat(kUnindexMap, R"lua(
local p, id, name = ARGV[1], ARGV[2], ARGV[3]
local version = tonumber(ARGV[9])
if version == 0 then version = tonumber(redis.call('HGET', p .. 'map:' .. id, 'version') or '0') end
if version == 0 then version = redis.call('HINCRBY', p .. 'mapnames', name, 1) end
unindex_map(p, id)
local member = ARGV[7] .. ':' .. id
redis.call('HSET', p .. 'map:' .. id, 'name', name, 'format', ARGV[4], 'content_hash', ARGV[5],
           'source', ARGV[6], 'created_us', ARGV[7], 'info', ARGV[8], 'version', version)
redis.call('ZADD', p .. 'maps', 0, member)
redis.call('ZADD', p .. 'mapversions:' .. name, version, id)
return version
)lua"));
  return *script;
}

const std::string& DeleteMapScript() {
  static const auto* script =
      new std::string(absl::StrCat(kUnindexMap, "return unindex_map(ARGV[1], ARGV[2])\n"));
  return *script;
}

// ARGV: prefix, '1' for the sources or '0', ids...
constexpr const char* kGetMaps = R"lua(
local p = ARGV[1]
local out = {}
for i = 3, #ARGV do
  local fields = {'name', 'format', 'content_hash', 'created_us', 'info', 'version'}
  if ARGV[2] == '1' then fields[#fields + 1] = 'source' end
  out[#out + 1] = redis.call('HMGET', p .. 'map:' .. ARGV[i], unpack(fields))
end
return out
)lua";

// ARGV: prefix, then the job (JobRecordArgs).
const std::string& PutJobScript() {
  static const auto* script =
      new std::string(absl::StrCat(kJobRecordLua, "put_job(ARGV[1], 2)\nreturn 1\n"));
  return *script;
}

// ARGV: prefix, ids...; deletes those still finished and returns them.
const std::string& DeleteFinishedScript() {
  static const auto* script = new std::string(absl::StrCat(kJobRecordLua, R"lua(
local p = ARGV[1]
local deleted = {}
for i = 2, #ARGV do
  if redis.call('HEXISTS', p .. 'job:' .. ARGV[i], 'finished_us') == 1 then
    unindex_job(p, ARGV[i])
    deleted[#deleted + 1] = ARGV[i]
  end
end
return deleted
)lua"));
  return *script;
}

constexpr const char* kGetJobs = R"lua(
local p = ARGV[1]
local out = {}
for i = 2, #ARGV do
  out[#out + 1] = redis.call('HMGET', p .. 'job:' .. ARGV[i], 'state', 'record', 'created_us',
                             'finished_us', 'client_request_id')
end
return out
)lua";

// Ids per script call when deleting many jobs.
constexpr size_t kDeleteBatch = 500;

std::string Micros(absl::Time t) { return absl::StrCat(absl::ToUnixMicros(t)); }

std::string Member(int64_t created_us, const std::string& id) {
  return absl::StrCat(PaddedMicros(created_us), ":", id);
}
std::string IdOfMember(const std::string& member) {
  const size_t colon = member.find(':');
  return colon == std::string::npos ? member : member.substr(colon + 1);
}

absl::Status Corrupt(const std::string& what, const std::string& id) {
  return absl::DataLossError(absl::StrCat(what, " '", id, "': stored fields are corrupt"));
}

int64_t ParseMicros(const RedisReply& r, bool* ok) {
  int64_t us = 0;
  if (r.type != RedisReply::Type::kString || !absl::SimpleAtoi(r.str, &us)) *ok = false;
  return us;
}

}  // namespace

absl::StatusOr<std::unique_ptr<RedisStore>> RedisStore::Open(const RedisEndpoint& endpoint,
                                                             std::string prefix) {
  absl::StatusOr<std::unique_ptr<RedisClient>> client = RedisClient::Connect(endpoint);
  if (!client.ok()) return client.status();
  return std::unique_ptr<RedisStore>(new RedisStore(std::move(*client), std::move(prefix)));
}

absl::StatusOr<int64_t> RedisStore::PutMap(const StoredMap& map) {
  absl::StatusOr<RedisReply> version = client_->Eval(
      PutMapScript(), {},
      {prefix_, map.id, map.name, map.format, map.content_hash, map.source,
       PaddedMicros(absl::ToUnixMicros(map.created_at)), map.info, absl::StrCat(map.version)});
  if (!version.ok()) return version.status();
  return version->integer;
}

absl::StatusOr<std::vector<StoredMap>> RedisStore::GetMaps(const std::vector<std::string>& ids,
                                                           bool with_source) {
  std::vector<StoredMap> maps;
  if (ids.empty()) return maps;
  std::vector<std::string> args = {prefix_, with_source ? "1" : "0"};
  args.insert(args.end(), ids.begin(), ids.end());
  absl::StatusOr<RedisReply> reply = client_->Eval(kGetMaps, {}, args);
  if (!reply.ok()) return reply.status();
  for (size_t i = 0; i < ids.size() && i < reply->elements.size(); ++i) {
    const std::vector<RedisReply>& f = reply->elements[i].elements;
    if (f.size() < 6 || f[0].nil()) continue;  // deleted meanwhile
    bool ok = true;
    StoredMap map{ids[i],
                  f[0].str,
                  f[1].str,
                  f[2].str,
                  with_source && f.size() > 6 ? f[6].str : "",
                  absl::FromUnixMicros(ParseMicros(f[3], &ok)),
                  f[4].str};
    // Maps stored before maps had versions have none (0).
    if (!f[5].nil() && !absl::SimpleAtoi(f[5].str, &map.version)) ok = false;
    if (!ok) return Corrupt("map", ids[i]);
    maps.push_back(std::move(map));
  }
  return maps;
}

absl::StatusOr<StoredMap> RedisStore::GetMap(const std::string& id) {
  absl::StatusOr<std::vector<StoredMap>> maps = GetMaps({id}, /*with_source=*/true);
  if (!maps.ok()) return maps.status();
  if (maps->empty()) return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
  return std::move(maps->front());
}

absl::StatusOr<StoredMap> RedisStore::GetMapInfo(const std::string& id) {
  absl::StatusOr<std::vector<StoredMap>> maps = GetMaps({id}, /*with_source=*/false);
  if (!maps.ok()) return maps.status();
  if (maps->empty()) return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
  return std::move(maps->front());
}

absl::StatusOr<std::vector<StoredMap>> RedisStore::ListMaps(const MapCursor* after, int limit) {
  const std::string min =
      after == nullptr ? "-" : absl::StrCat("(", Member(after->created_us, after->id));
  absl::StatusOr<RedisReply> members =
      client_->Command({"ZRANGE", prefix_ + "maps", min, "+", "BYLEX", "LIMIT", "0",
                        absl::StrCat(std::max(limit, 0))});
  if (!members.ok()) return members.status();
  std::vector<std::string> ids;
  for (const RedisReply& m : members->elements) ids.push_back(IdOfMember(m.str));
  return GetMaps(ids, /*with_source=*/false);
}

absl::StatusOr<StoredMap> RedisStore::FindMapVersion(const std::string& name, int64_t version) {
  const std::string key = absl::StrCat(prefix_, "mapversions:", name);
  absl::StatusOr<RedisReply> ids =
      version > 0
          ? client_->Command({"ZRANGE", key, absl::StrCat(version), absl::StrCat(version),
                              "BYSCORE", "LIMIT", "0", "1"})
          : client_->Command({"ZRANGE", key, "+inf", "-inf", "BYSCORE", "REV", "LIMIT", "0", "1"});
  if (!ids.ok()) return ids.status();
  absl::StatusOr<StoredMap> map =
      ids->elements.empty() ? absl::NotFoundError("") : GetMapInfo(ids->elements.front().str);
  if (absl::IsNotFound(map.status())) return NoSuchMapVersion(name, version);
  return map;
}

absl::StatusOr<std::vector<StoredMap>> RedisStore::ListMapVersions(const std::string& name,
                                                                   int64_t after_version,
                                                                   int limit) {
  absl::StatusOr<RedisReply> members = client_->Command(
      {"ZRANGE", absl::StrCat(prefix_, "mapversions:", name), absl::StrCat("(", after_version),
       "+inf", "BYSCORE", "LIMIT", "0", absl::StrCat(std::max(limit, 0))});
  if (!members.ok()) return members.status();
  std::vector<std::string> ids;
  for (const RedisReply& m : members->elements) ids.push_back(m.str);
  return GetMaps(ids, /*with_source=*/false);
}

absl::StatusOr<int64_t> RedisStore::CountMaps() {
  absl::StatusOr<RedisReply> n = client_->Command({"ZCARD", prefix_ + "maps"});
  if (!n.ok()) return n.status();
  return n->integer;
}

absl::Status RedisStore::DeleteMap(const std::string& id) {
  absl::StatusOr<RedisReply> deleted = client_->Eval(DeleteMapScript(), {}, {prefix_, id});
  if (!deleted.ok()) return deleted.status();
  if (deleted->integer == 0) return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
  return absl::OkStatus();
}

absl::Status RedisStore::PutJob(const StoredJob& job) {
  std::vector<std::string> args = {prefix_};
  for (std::string& arg : JobRecordArgs(job)) args.push_back(std::move(arg));
  return client_->Eval(PutJobScript(), {}, args).status();
}

absl::StatusOr<std::vector<StoredJob>> RedisStore::GetJobs(const std::vector<std::string>& ids) {
  std::vector<StoredJob> jobs;
  if (ids.empty()) return jobs;
  std::vector<std::string> args = {prefix_};
  args.insert(args.end(), ids.begin(), ids.end());
  absl::StatusOr<RedisReply> reply = client_->Eval(kGetJobs, {}, args);
  if (!reply.ok()) return reply.status();
  for (size_t i = 0; i < ids.size() && i < reply->elements.size(); ++i) {
    const std::vector<RedisReply>& f = reply->elements[i].elements;
    if (f.size() != 5 || f[0].nil()) continue;  // deleted meanwhile
    StoredJob job;
    job.id = ids[i];
    bool ok = absl::SimpleAtoi(f[0].str, &job.state);
    job.record = f[1].str;
    job.created_at = absl::FromUnixMicros(ParseMicros(f[2], &ok));
    if (!f[3].nil()) job.finished_at = absl::FromUnixMicros(ParseMicros(f[3], &ok));
    job.client_request_id = f[4].str;
    if (!ok) return Corrupt("job", ids[i]);
    jobs.push_back(std::move(job));
  }
  return jobs;
}

absl::StatusOr<StoredJob> RedisStore::GetJob(const std::string& id) {
  absl::StatusOr<std::vector<StoredJob>> jobs = GetJobs({id});
  if (!jobs.ok()) return jobs.status();
  if (jobs->empty()) return absl::NotFoundError(absl::StrCat("job '", id, "' not found"));
  return std::move(jobs->front());
}

absl::StatusOr<std::vector<std::string>> RedisStore::NewestMembers(const std::string& key,
                                                                   const JobCursor* before,
                                                                   int limit) {
  const std::string max =
      before == nullptr ? "+" : absl::StrCat("(", Member(before->created_us, before->id));
  absl::StatusOr<RedisReply> reply = client_->Command(
      {"ZRANGE", key, max, "-", "BYLEX", "REV", "LIMIT", "0", absl::StrCat(std::max(limit, 0))});
  if (!reply.ok()) return reply.status();
  std::vector<std::string> members;
  for (const RedisReply& m : reply->elements) members.push_back(m.str);
  return members;
}

absl::StatusOr<StoredJob> RedisStore::FindJobByClientRequestId(const std::string& id) {
  absl::StatusOr<std::vector<std::string>> newest =
      NewestMembers(prefix_ + "crid:" + id, nullptr, 1);
  if (!newest.ok()) return newest.status();
  absl::StatusOr<StoredJob> job =
      newest->empty() ? absl::NotFoundError("") : GetJob(IdOfMember(newest->front()));
  if (absl::IsNotFound(job.status())) {
    return absl::NotFoundError(absl::StrCat("no job with client_request_id '", id, "'"));
  }
  return job;
}

absl::StatusOr<std::vector<StoredJob>> RedisStore::LoadJobsToRecover() {
  absl::StatusOr<RedisReply> members =
      client_->Command({"ZRANGE", prefix_ + "jobs:unfinished", "-", "+", "BYLEX"});
  if (!members.ok()) return members.status();
  std::vector<std::string> ids;
  for (const RedisReply& m : members->elements) ids.push_back(IdOfMember(m.str));
  return GetJobs(ids);
}

absl::StatusOr<std::vector<StoredJob>> RedisStore::ListJobs(const JobCursor* before,
                                                            const std::vector<int>& states,
                                                            int limit) {
  std::vector<std::string> keys;
  if (states.empty()) keys.push_back(prefix_ + "jobs");
  for (int state : states) keys.push_back(absl::StrCat(prefix_, "jobs:state:", state));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<std::string> members;
  for (const std::string& key : keys) {
    absl::StatusOr<std::vector<std::string>> newest = NewestMembers(key, before, limit);
    if (!newest.ok()) return newest.status();
    members.insert(members.end(), newest->begin(), newest->end());
  }
  std::sort(members.begin(), members.end(), std::greater<>());
  if (members.size() > static_cast<size_t>(std::max(limit, 0))) members.resize(limit);
  std::vector<std::string> ids;
  for (const std::string& m : members) ids.push_back(IdOfMember(m));
  return GetJobs(ids);
}

absl::StatusOr<int64_t> RedisStore::CountFinishedJobs() {
  absl::StatusOr<RedisReply> n = client_->Command({"ZCARD", prefix_ + "jobs:finished"});
  if (!n.ok()) return n.status();
  return n->integer;
}

absl::StatusOr<std::vector<std::string>> RedisStore::DeleteFinished(
    const std::vector<std::string>& ids) {
  std::vector<std::string> deleted;
  for (size_t first = 0; first < ids.size(); first += kDeleteBatch) {
    std::vector<std::string> args = {prefix_};
    const size_t last = std::min(ids.size(), first + kDeleteBatch);
    args.insert(args.end(), ids.begin() + first, ids.begin() + last);
    absl::StatusOr<RedisReply> reply = client_->Eval(DeleteFinishedScript(), {}, args);
    if (!reply.ok()) return reply.status();
    for (const RedisReply& id : reply->elements) deleted.push_back(id.str);
  }
  return deleted;
}

absl::StatusOr<std::vector<std::string>> RedisStore::DeleteJobsFinishedBefore(absl::Time cutoff) {
  absl::StatusOr<RedisReply> ids = client_->Command(
      {"ZRANGE", prefix_ + "jobs:finished", "-inf", absl::StrCat("(", Micros(cutoff)), "BYSCORE"});
  if (!ids.ok()) return ids.status();
  std::vector<std::string> selected;
  for (const RedisReply& id : ids->elements) selected.push_back(id.str);
  return DeleteFinished(selected);
}

absl::StatusOr<std::vector<std::string>> RedisStore::DeleteOldestFinishedJobs(int64_t n) {
  if (n <= 0) return std::vector<std::string>();
  absl::StatusOr<RedisReply> ids =
      client_->Command({"ZRANGE", prefix_ + "jobs:finished", "0", absl::StrCat(n - 1)});
  if (!ids.ok()) return ids.status();
  std::vector<std::string> selected;
  for (const RedisReply& id : ids->elements) selected.push_back(id.str);
  return DeleteFinished(selected);
}

}  // namespace swarmplan::server
