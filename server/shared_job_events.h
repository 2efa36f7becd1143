#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "server/redis_client.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::server {

// Each job's events in a capped Redis stream, so that a replica other than the one running a
// job can follow it: the runner appends every event it publishes, followers read them after a
// cursor. Progress events are published at the rate the request asked for, so the cap (about
// `max_events` newest entries) only ever drops old progress of long runs; a follower that joins
// late takes the job's state from its stored record and the newest events from the stream. A
// stream expires `keep` after its last event. Thread-safe. Keys, under `prefix`:
//   events:ID    stream of {e: serialized swarmplan.v1.JobEvent}
class SharedJobEvents {
 public:
  SharedJobEvents(RedisClient& client, std::string prefix, int max_events = 256,
                  absl::Duration keep = absl::Hours(24))
      : client_(client), prefix_(std::move(prefix)), max_events_(max_events), keep_(keep) {}

  // Appends `event` to the stream of event.job_id(); returns its entry id.
  absl::StatusOr<std::string> Append(const v1::JobEvent& event);

  // Where a follower reads from: a job's stream after `after` ("0": from its oldest event).
  struct Cursor {
    std::string job_id;
    std::string after = "0";
  };
  struct Followed {
    std::string job_id;
    std::string entry;  // the next cursor of this job
    v1::JobEvent event;
  };
  // Up to `count` events per job after the cursors, oldest first per job, waiting up to `wait`
  // (at most 5 s) for the first when there is none yet. An entry that does not parse comes back
  // with an empty event (no case set), so that the cursor still moves past it.
  absl::StatusOr<std::vector<Followed>> Read(const std::vector<Cursor>& cursors,
                                             absl::Duration wait, int count = 64);

 private:
  RedisClient& client_;
  const std::string prefix_;
  const int max_events_;
  const absl::Duration keep_;
};

}  // namespace swarmplan::server
