#include "server/redis_job_lua.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace swarmplan::server {

const char kJobRecordLua[] = R"lua(
local function unindex_job(p, id)
  local key = p .. 'job:' .. id
  local old = redis.call('HMGET', key, 'state', 'created_us', 'client_request_id')
  if old[1] then
    local member = old[2] .. ':' .. id
    redis.call('ZREM', p .. 'jobs', member)
    redis.call('ZREM', p .. 'jobs:state:' .. old[1], member)
    redis.call('ZREM', p .. 'jobs:unfinished', member)
    if old[3] and old[3] ~= '' then redis.call('ZREM', p .. 'crid:' .. old[3], member) end
  end
  redis.call('ZREM', p .. 'jobs:finished', id)
  redis.call('DEL', key)
end

local function put_job(p, a)
  local id, state, record = ARGV[a], ARGV[a + 1], ARGV[a + 2]
  local created, finished, crid = ARGV[a + 3], ARGV[a + 4], ARGV[a + 5]
  unindex_job(p, id)
  local key = p .. 'job:' .. id
  local member = created .. ':' .. id
  redis.call('HSET', key, 'state', state, 'record', record, 'created_us', created,
             'client_request_id', crid)
  redis.call('ZADD', p .. 'jobs', 0, member)
  redis.call('ZADD', p .. 'jobs:state:' .. state, 0, member)
  if finished == '' then
    redis.call('ZADD', p .. 'jobs:unfinished', 0, member)
  else
    redis.call('HSET', key, 'finished_us', finished)
    redis.call('ZADD', p .. 'jobs:finished', finished, id)
  end
  if crid ~= '' then redis.call('ZADD', p .. 'crid:' .. crid, 0, member) end
end
)lua";

std::string PaddedMicros(int64_t us) { return absl::StrFormat("%020d", std::max<int64_t>(us, 0)); }

std::vector<std::string> JobRecordArgs(const StoredJob& job) {
  return {job.id,
          absl::StrCat(job.state),
          job.record,
          PaddedMicros(absl::ToUnixMicros(job.created_at)),
          job.finished_at == absl::InfiniteFuture()
              ? ""
              : absl::StrCat(absl::ToUnixMicros(job.finished_at)),
          job.client_request_id};
}

}  // namespace swarmplan::server
