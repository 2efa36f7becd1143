#include "server/job_events.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "server/proto_convert.h"

namespace swarmplan::server {

bool IsLastEvent(const v1::JobEvent& event) { return event.has_finished() || event.has_requeued(); }

void EventDoorbell::Ring() {
  absl::MutexLock lock(&mu_);
  if (ring_) ring_();
}

void EventDoorbell::Detach() {
  absl::MutexLock lock(&mu_);
  ring_ = nullptr;
}

EventPtr JobEvents::Publish(v1::JobEvent event) {
  std::vector<std::shared_ptr<EventDoorbell>> watchers;
  EventPtr published;
  {
    absl::MutexLock lock(&mu_);
    if (finished_) return nullptr;
    event.set_job_id(job_id_);
    event.set_sequence(++sequence_);
    *event.mutable_time() = ToProto(absl::Now());
    auto ptr = std::make_shared<const v1::JobEvent>(std::move(event));
    published = ptr;
    if (ptr->has_progress()) {
      latest_progress_ = std::move(ptr);
    } else {
      finished_ = IsLastEvent(*ptr);
      milestones_.push_back(std::move(ptr));
    }
    watchers = watchers_;
  }
  for (const auto& w : watchers) w->Ring();
  return published;
}

EventPtr JobEvents::Next(int64_t after) const {
  absl::MutexLock lock(&mu_);
  EventPtr next;
  for (const EventPtr& e : milestones_) {
    if (e->sequence() > after) {
      next = e;
      break;
    }
  }
  if (latest_progress_ != nullptr && latest_progress_->sequence() > after &&
      (next == nullptr || latest_progress_->sequence() < next->sequence())) {
    next = latest_progress_;
  }
  return next;
}

int64_t JobEvents::LatestStateCursor() const {
  absl::MutexLock lock(&mu_);
  return milestones_.empty() ? 0 : milestones_.back()->sequence() - 1;
}

bool JobEvents::finished() const {
  absl::MutexLock lock(&mu_);
  return finished_;
}

absl::StatusOr<std::shared_ptr<EventDoorbell>> JobEvents::AddWatcher(std::function<void()> ring,
                                                                     int max_watchers) {
  absl::MutexLock lock(&mu_);
  if (static_cast<int>(watchers_.size()) >= max_watchers) {
    return absl::ResourceExhaustedError(
        absl::StrCat("job ", job_id_, " already has ", watchers_.size(),
                     " watchers, the server's limit (--max-watchers-per-job)"));
  }
  auto doorbell = std::make_shared<EventDoorbell>(std::move(ring));
  watchers_.push_back(doorbell);
  return doorbell;
}

int JobEvents::RemoveWatcher(const std::shared_ptr<EventDoorbell>& doorbell) {
  doorbell->Detach();
  absl::MutexLock lock(&mu_);
  watchers_.erase(std::remove(watchers_.begin(), watchers_.end(), doorbell), watchers_.end());
  return static_cast<int>(watchers_.size());
}

}  // namespace swarmplan::server
