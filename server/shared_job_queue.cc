#include "server/shared_job_queue.h"

#include <unistd.h>

#include <algorithm>
#include <map>
#include <random>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/synchronization/mutex.h"
#include "server/redis_job_lua.h"

namespace swarmplan::server {
namespace {

constexpr char kGroup[] = "workers";
// Every script takes the key prefix as ARGV[1].
constexpr char kQueueLua[] = R"lua(
local function queue_key(p) return p .. 'queue' end

-- Jobs in the stream that no replica has taken.
local function waiting(p)
  local q = queue_key(p)
  return redis.call('XLEN', q) - redis.call('XPENDING', q, 'workers')[1]
end

-- Whether consumer `me` holds `entry` and the job's attempt `attempt` is still the last begun.
local function held(p, entry, id, me, attempt)
  local pending = redis.call('XPENDING', queue_key(p), 'workers', entry, entry, 1)
  if #pending == 0 or pending[1][2] ~= me then return false end
  local run = redis.call('HMGET', p .. 'run:' .. id, 'attempt', 'consumer')
  return run[1] == attempt and run[2] == me
end

local function forget(p, id)
  redis.call('DEL', p .. 'queued:' .. id, p .. 'run:' .. id, p .. 'cancel:' .. id)
end
)lua";

// ARGV: prefix, capacity (-1: none), the job (JobRecordArgs).
constexpr char kPush[] = R"lua(
local p = ARGV[1]
local ahead = waiting(p)
local capacity = tonumber(ARGV[2])
if capacity >= 0 and ahead >= capacity then return -1 end
put_job(p, 3)
local id = ARGV[3]
local entry = redis.call('XADD', queue_key(p), '*', 'job', id)
redis.call('SET', p .. 'queued:' .. id, entry)
return ahead
)lua";

// ARGV: prefix, entry, job id, consumer. The attempt begun; 0 when the job finished meanwhile
// (its entry is dropped); -1 when another consumer holds the entry now.
constexpr char kBegin[] = R"lua(
local p, entry, id, me = ARGV[1], ARGV[2], ARGV[3], ARGV[4]
local q = queue_key(p)
local key = p .. 'job:' .. id
if redis.call('EXISTS', key) == 0 or redis.call('HEXISTS', key, 'finished_us') == 1 then
  redis.call('XACK', q, 'workers', entry)
  redis.call('XDEL', q, entry)
  if redis.call('GET', p .. 'queued:' .. id) == entry then forget(p, id) end
  return 0
end
local pending = redis.call('XPENDING', q, 'workers', entry, entry, 1)
if #pending == 0 or pending[1][2] ~= me then return -1 end
local attempt = redis.call('HINCRBY', p .. 'run:' .. id, 'attempt', 1)
redis.call('HSET', p .. 'run:' .. id, 'consumer', me, 'entry', entry)
return attempt
)lua";

// ARGV: prefix, entry, job id, consumer, attempt.
constexpr char kRenew[] = R"lua(
local p = ARGV[1]
if not held(p, ARGV[2], ARGV[3], ARGV[4], ARGV[5]) then return 0 end
redis.call('XCLAIM', queue_key(p), 'workers', ARGV[4], 0, ARGV[2], 'JUSTID')
return 1
)lua";

// ARGV: prefix, entry, job id, consumer, attempt, '1' for a final state, the job from ARGV[7].
constexpr char kRecord[] = R"lua(
local p, entry, id, me = ARGV[1], ARGV[2], ARGV[3], ARGV[4]
if not held(p, entry, id, me, ARGV[5]) then return 0 end
put_job(p, 7)
local q = queue_key(p)
if ARGV[6] == '1' then
  redis.call('XACK', q, 'workers', entry)
  redis.call('XDEL', q, entry)
  forget(p, id)
else
  redis.call('XCLAIM', q, 'workers', me, 0, entry, 'JUSTID')
end
return 1
)lua";

// ARGV: prefix, entry, job id, consumer, attempt, the job from ARGV[6].
constexpr char kRelease[] = R"lua(
local p, entry, id, me = ARGV[1], ARGV[2], ARGV[3], ARGV[4]
if not held(p, entry, id, me, ARGV[5]) then return 0 end
put_job(p, 6)
local q = queue_key(p)
redis.call('XACK', q, 'workers', entry)
redis.call('XDEL', q, entry)
redis.call('SET', p .. 'queued:' .. id, redis.call('XADD', q, '*', 'job', id))
redis.call('HDEL', p .. 'run:' .. id, 'consumer', 'entry')
return 1
)lua";

// ARGV: prefix, the job from ARGV[2].
constexpr char kRemoveWaiting[] = R"lua(
local p, id = ARGV[1], ARGV[2]
local q = queue_key(p)
local entry = redis.call('GET', p .. 'queued:' .. id)
if not entry then return 0 end
if #redis.call('XPENDING', q, 'workers', entry, entry, 1) > 0 then return 0 end
if #redis.call('XRANGE', q, entry, entry) == 0 then return 0 end
redis.call('XDEL', q, entry)
forget(p, id)
put_job(p, 2)
return 1
)lua";

constexpr char kWaiting[] = "return waiting(ARGV[1])\n";

// The script of one of the bodies above, with the Lua it calls.
const std::string& Script(const char* body) {
  static absl::Mutex mu;
  static auto* scripts = new std::map<const char*, std::string>();  // stable references
  absl::MutexLock lock(&mu);
  auto [it, added] = scripts->try_emplace(body);
  if (added) it->second = absl::StrCat(kJobRecordLua, kQueueLua, body);
  return it->second;
}

bool IsFinished(const StoredJob& job) { return job.finished_at != absl::InfiniteFuture(); }

void Append(std::vector<std::string>& args, const StoredJob& job) {
  for (std::string& arg : JobRecordArgs(job)) args.push_back(std::move(arg));
}

// The job id of a stream entry's fields {job: ID}; "" when absent.
std::string JobOfFields(const RedisReply& fields) {
  for (size_t i = 0; i + 1 < fields.elements.size(); i += 2) {
    if (fields.elements[i].str == "job") return fields.elements[i + 1].str;
  }
  return "";
}

}  // namespace

std::string UniqueConsumerName() {
  char host[256] = {};
  if (gethostname(host, sizeof(host) - 1) != 0) host[0] = '\0';
  std::random_device random;
  return absl::StrFormat("%s:%d:%08x", host[0] != '\0' ? host : "replica", getpid(), random());
}

absl::StatusOr<std::unique_ptr<SharedJobQueue>> SharedJobQueue::Open(RedisClient& client,
                                                                     std::string prefix,
                                                                     Options options) {
  if (options.consumer.empty()) options.consumer = UniqueConsumerName();
  absl::StatusOr<RedisReply> created =
      client.Command({"XGROUP", "CREATE", prefix + "queue", kGroup, "0", "MKSTREAM"});
  if (!created.ok() && !absl::StrContains(created.status().message(), "BUSYGROUP")) {
    return created.status();
  }
  return std::unique_ptr<SharedJobQueue>(
      new SharedJobQueue(client, std::move(prefix), std::move(options)));
}

std::vector<std::string> SharedJobQueue::LeaseArgs(const JobLease& lease) const {
  return {prefix_, lease.entry, lease.job_id, options_.consumer, absl::StrCat(lease.attempt)};
}

absl::StatusOr<int64_t> SharedJobQueue::Push(const StoredJob& job, bool ignore_capacity) {
  std::vector<std::string> args = {prefix_,
                                   ignore_capacity ? "-1" : absl::StrCat(options_.capacity)};
  Append(args, job);
  absl::StatusOr<RedisReply> ahead = client_.Eval(Script(kPush), {}, args);
  if (!ahead.ok()) return ahead.status();
  if (ahead->integer < 0) {
    return absl::ResourceExhaustedError(
        absl::StrCat("the shared queue is full: ", options_.capacity,
                     " jobs wait across all replicas (--queue-capacity); try again later"));
  }
  return ahead->integer;
}

absl::StatusOr<std::optional<JobLease>> SharedJobQueue::Begin(const std::string& entry,
                                                              const RedisReply& fields,
                                                              bool reclaimed) {
  const std::string job_id = JobOfFields(fields);
  if (job_id.empty()) {
    // Not an entry this queue wrote: drop it so that it does not come back.
    (void)client_.Command({"XACK", prefix_ + "queue", kGroup, entry});
    (void)client_.Command({"XDEL", prefix_ + "queue", entry});
    return std::nullopt;
  }
  absl::StatusOr<RedisReply> attempt =
      client_.Eval(Script(kBegin), {}, {prefix_, entry, job_id, options_.consumer});
  if (!attempt.ok()) return attempt.status();
  if (attempt->integer <= 0) return std::nullopt;
  return JobLease{job_id, entry, attempt->integer, reclaimed};
}

absl::StatusOr<std::optional<JobLease>> SharedJobQueue::Take(absl::Duration wait) {
  const std::string queue = prefix_ + "queue";
  // Leases that ran out come first: their jobs have waited longest.
  std::string cursor = "0-0";
  do {
    absl::StatusOr<RedisReply> claimed =
        client_.Command({"XAUTOCLAIM", queue, kGroup, options_.consumer,
                         RedisMillis(options_.lease), cursor, "COUNT", "1"});
    if (!claimed.ok()) return claimed.status();
    if (claimed->elements.size() < 2) break;
    cursor = claimed->elements[0].str;
    for (const RedisReply& entry : claimed->elements[1].elements) {
      if (entry.elements.size() != 2 || entry.elements[1].nil()) continue;
      absl::StatusOr<std::optional<JobLease>> lease =
          Begin(entry.elements[0].str, entry.elements[1], /*reclaimed=*/true);
      if (!lease.ok() || lease->has_value()) return lease;
    }
  } while (cursor != "0-0");

  absl::StatusOr<RedisReply> read =
      client_.Command({"XREADGROUP", "GROUP", kGroup, options_.consumer, "COUNT", "1", "BLOCK",
                       RedisMillis(std::min(wait, kMaxRedisBlock)), "STREAMS", queue, ">"});
  if (!read.ok()) return read.status();
  // [[queue, [[entry, [field, value, ...]]]]], or nil after the wait.
  if (read->elements.empty() || read->elements[0].elements.size() < 2) return std::nullopt;
  for (const RedisReply& entry : read->elements[0].elements[1].elements) {
    if (entry.elements.size() != 2) continue;
    return Begin(entry.elements[0].str, entry.elements[1], /*reclaimed=*/false);
  }
  return std::nullopt;
}

absl::StatusOr<bool> SharedJobQueue::Renew(const JobLease& lease) {
  absl::StatusOr<RedisReply> renewed = client_.Eval(Script(kRenew), {}, LeaseArgs(lease));
  if (!renewed.ok()) return renewed.status();
  return renewed->integer == 1;
}

absl::StatusOr<bool> SharedJobQueue::Record(const JobLease& lease, const StoredJob& job) {
  std::vector<std::string> args = LeaseArgs(lease);
  args.push_back(IsFinished(job) ? "1" : "0");
  Append(args, job);
  absl::StatusOr<RedisReply> recorded = client_.Eval(Script(kRecord), {}, args);
  if (!recorded.ok()) return recorded.status();
  return recorded->integer == 1;
}

absl::StatusOr<bool> SharedJobQueue::Release(const JobLease& lease, const StoredJob& job) {
  std::vector<std::string> args = LeaseArgs(lease);
  Append(args, job);
  absl::StatusOr<RedisReply> released = client_.Eval(Script(kRelease), {}, args);
  if (!released.ok()) return released.status();
  return released->integer == 1;
}

absl::StatusOr<bool> SharedJobQueue::RemoveWaiting(const StoredJob& job) {
  std::vector<std::string> args = {prefix_};
  Append(args, job);
  absl::StatusOr<RedisReply> removed = client_.Eval(Script(kRemoveWaiting), {}, args);
  if (!removed.ok()) return removed.status();
  return removed->integer == 1;
}

absl::Status SharedJobQueue::RequestCancel(const std::string& job_id, absl::Duration ttl) {
  return client_
      .Command({"SET", prefix_ + "cancel:" + job_id, "1", "PX",
                RedisMillis(std::max(ttl, absl::Milliseconds(1)))})
      .status();
}

absl::StatusOr<std::vector<bool>> SharedJobQueue::CancelRequested(
    const std::vector<std::string>& job_ids) {
  std::vector<bool> requested(job_ids.size(), false);
  if (job_ids.empty()) return requested;
  std::vector<std::string> args = {"MGET"};
  for (const std::string& id : job_ids) args.push_back(prefix_ + "cancel:" + id);
  absl::StatusOr<RedisReply> flags = client_.Command(args);
  if (!flags.ok()) return flags.status();
  for (size_t i = 0; i < job_ids.size() && i < flags->elements.size(); ++i) {
    requested[i] = !flags->elements[i].nil();
  }
  return requested;
}

absl::StatusOr<int64_t> SharedJobQueue::Waiting() {
  absl::StatusOr<RedisReply> n = client_.Eval(Script(kWaiting), {}, {prefix_});
  if (!n.ok()) return n.status();
  return n->integer;
}

}  // namespace swarmplan::server
