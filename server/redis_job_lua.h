#pragma once

#include <string>
#include <vector>

#include "server/store.h"

namespace swarmplan::server {

// Lua shared by every script that writes job records (RedisStore, SharedJobQueue), so a record
// and its indexes change in one place. Defines, for the key prefix `p`:
//   unindex_job(p, id)  removes the job from every index and deletes its hash;
//   put_job(p, a)       writes the job whose fields are ARGV[a .. a + 5] (JobRecordArgs).
extern const char kJobRecordLua[];

// ARGV of put_job, in order: id, state, record, created_us (20 digits), finished_us ("" while
// unfinished), client_request_id.
std::vector<std::string> JobRecordArgs(const StoredJob& job);

// 20 digits: sorted-set members "CREATED_US:ID" order lexicographically by time, then id.
std::string PaddedMicros(int64_t us);

}  // namespace swarmplan::server
