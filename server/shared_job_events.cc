#include "server/shared_job_events.h"

#include <algorithm>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"

namespace swarmplan::server {
namespace {

// ARGV: prefix, job id, serialized event, max events, keep (ms).
constexpr char kAppend[] = R"lua(
local key = ARGV[1] .. 'events:' .. ARGV[2]
local entry = redis.call('XADD', key, 'MAXLEN', '~', ARGV[4], '*', 'e', ARGV[3])
redis.call('PEXPIRE', key, ARGV[5])
return entry
)lua";

}  // namespace

absl::StatusOr<std::string> SharedJobEvents::Append(const v1::JobEvent& event) {
  if (event.job_id().empty()) return absl::InvalidArgumentError("job_id: required");
  absl::StatusOr<RedisReply> entry =
      client_.Eval(kAppend, {},
                   {prefix_, event.job_id(), event.SerializeAsString(), absl::StrCat(max_events_),
                    RedisMillis(keep_)});
  if (!entry.ok()) return entry.status();
  return entry->str;
}

absl::StatusOr<std::vector<SharedJobEvents::Followed>> SharedJobEvents::Read(
    const std::vector<Cursor>& cursors, absl::Duration wait, int count) {
  std::vector<Followed> out;
  if (cursors.empty()) return out;
  std::vector<std::string> args = {"XREAD", "COUNT", absl::StrCat(std::max(count, 1))};
  if (wait > absl::ZeroDuration()) {
    args.push_back("BLOCK");
    args.push_back(RedisMillis(std::min(wait, kMaxRedisBlock)));
  }
  args.push_back("STREAMS");
  const std::string key_prefix = prefix_ + "events:";
  for (const Cursor& c : cursors) args.push_back(key_prefix + c.job_id);
  for (const Cursor& c : cursors) args.push_back(c.after.empty() ? "0" : c.after);
  absl::StatusOr<RedisReply> reply = client_.Command(args);
  if (!reply.ok()) return reply.status();
  // nil after the wait, else [[key, [[entry, [field, value, ...]], ...]], ...].
  for (const RedisReply& stream : reply->elements) {
    if (stream.elements.size() != 2 || !absl::StartsWith(stream.elements[0].str, key_prefix)) {
      continue;
    }
    const std::string job_id = stream.elements[0].str.substr(key_prefix.size());
    for (const RedisReply& entry : stream.elements[1].elements) {
      if (entry.elements.size() != 2) continue;
      Followed followed{job_id, entry.elements[0].str, {}};
      const std::vector<RedisReply>& fields = entry.elements[1].elements;
      bool parsed = false;
      for (size_t i = 0; i + 1 < fields.size(); i += 2) {
        if (fields[i].str == "e") parsed = followed.event.ParseFromString(fields[i + 1].str);
      }
      if (!parsed) followed.event.Clear();
      out.push_back(std::move(followed));
    }
  }
  return out;
}

}  // namespace swarmplan::server
