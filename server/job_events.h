#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::server {

using EventPtr = std::shared_ptr<const v1::JobEvent>;

// finished, or requeued at a shutdown: nothing follows it in this server process.
bool IsLastEvent(const v1::JobEvent& event);

// A watcher's doorbell: the buffer rings it when events arrive. Detach() guarantees that the
// callback is not running and will not run again.
class EventDoorbell {
 public:
  explicit EventDoorbell(std::function<void()> ring) : ring_(std::move(ring)) {}
  void Ring();
  void Detach();

 private:
  absl::Mutex mu_;
  std::function<void()> ring_ ABSL_GUARDED_BY(mu_);
};

// The events of one job. Publishing never blocks on a watcher: milestones (accepted, started,
// finished or requeued) are all kept; of the progress events only the latest is kept, so a slow
// watcher skips to the newest progress, and never misses a milestone. Thread-safe.
class JobEvents {
 public:
  explicit JobEvents(std::string job_id) : job_id_(std::move(job_id)) {}

  // Stamps the event with the job id, the next sequence number and the time, then rings every
  // watcher. Nothing is published after a finished or requeued event (IsLastEvent): then
  // returns nullptr, else the event as published.
  EventPtr Publish(v1::JobEvent event);

  // The first event after sequence `after` that a watcher should see, or nullptr.
  EventPtr Next(int64_t after) const;
  // Where a watcher that wants "latest state first, then live" starts.
  int64_t LatestStateCursor() const;
  bool finished() const;

  // RESOURCE_EXHAUSTED beyond `max_watchers`.
  absl::StatusOr<std::shared_ptr<EventDoorbell>> AddWatcher(std::function<void()> ring,
                                                            int max_watchers);
  // Returns how many watchers remain.
  int RemoveWatcher(const std::shared_ptr<EventDoorbell>& doorbell);

 private:
  const std::string job_id_;
  mutable absl::Mutex mu_;
  int64_t sequence_ ABSL_GUARDED_BY(mu_) = 0;
  std::vector<EventPtr> milestones_ ABSL_GUARDED_BY(mu_);
  EventPtr latest_progress_ ABSL_GUARDED_BY(mu_);
  bool finished_ ABSL_GUARDED_BY(mu_) = false;
  std::vector<std::shared_ptr<EventDoorbell>> watchers_ ABSL_GUARDED_BY(mu_);
};

}  // namespace swarmplan::server
