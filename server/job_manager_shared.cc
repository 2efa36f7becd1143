// JobManager with SharedJobs: the feeder, the keeper and the relay (job_manager.h).
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "server/job_manager.h"
#include "server/proto_convert.h"

namespace swarmplan::server {
namespace {

// Progress reaches a job's shared stream at most this often; milestones always do.
constexpr absl::Duration kShareProgressEvery = absl::Milliseconds(100);
// How often the keeper looks for cancellations asked for on other replicas.
constexpr absl::Duration kCancelPoll = absl::Milliseconds(50);
// A followed job without events for this long is compared with its stored record.
constexpr absl::Duration kFollowedStoreCheck = absl::Seconds(1);
// The longest a loop waits in Redis, so that it notices a stop.
constexpr absl::Duration kLoopWait = absl::Milliseconds(250);
// The relay's wait: a job followed meanwhile joins its next read, so this bounds how late the
// first events of a newly followed job arrive.
constexpr absl::Duration kRelayWait = absl::Milliseconds(50);
constexpr absl::Duration kRetryAfterError = absl::Milliseconds(500);
constexpr absl::Duration kDepthReportEvery = absl::Seconds(1);

// A stream entry id "MS-SEQ" as a comparable pair; {0, 0} for "0" and anything unparsable.
std::pair<uint64_t, uint64_t> EntryOrder(const std::string& entry) {
  unsigned long long ms = 0, seq = 0;
  if (std::sscanf(entry.c_str(), "%llu-%llu", &ms, &seq) < 1) return {0, 0};
  return {ms, seq};
}

void SleepUnless(const std::atomic<bool>& stop, absl::Duration d) {
  const absl::Time end = absl::Now() + d;
  while (!stop.load() && absl::Now() < end) {
    absl::SleepFor(std::min(d, absl::Milliseconds(20)));
  }
}

}  // namespace

void JobManager::StartShared() {
  feeder_ = std::thread([this] { FeedLoop(); });
  keeper_ = std::thread([this] { KeepLoop(); });
  relay_ = std::thread([this] { RelayLoop(); });
}

void JobManager::StopFeeding() {
  stop_feeding_.store(true);
  if (feeder_.joinable()) feeder_.join();
}

void JobManager::StopShared() {
  StopFeeding();
  stop_shared_.store(true);
  if (keeper_.joinable()) keeper_.join();
  if (relay_.joinable()) relay_.join();
}

void JobManager::FeedLoop() {
  while (!stop_feeding_.load()) {
    if (!queue_->WaitForFreeWorker(kLoopWait)) continue;
    absl::StatusOr<std::optional<JobLease>> lease = shared_.queue->Take(kLoopWait);
    if (!lease.ok()) {
      spdlog::warn("shared queue: cannot take a job: {}", lease.status().ToString());
      SleepUnless(stop_feeding_, kRetryAfterError);
      continue;
    }
    if (lease->has_value()) RunLeased(**lease);
  }
}

void JobManager::RunLeased(const JobLease& lease) {
  if (lease.reclaimed) {
    metrics_.JobReclaimed();
    spdlog::info("job {}: attempt {} taken over from a replica whose lease ran out", lease.job_id,
                 lease.attempt);
  }
  // The stored record is the truth: another replica may have run an earlier attempt.
  absl::StatusOr<StoredJob> stored = store_.GetJob(lease.job_id);
  if (!stored.ok()) {
    spdlog::warn("job {}: cannot read its record ({}); its lease runs out", lease.job_id,
                 stored.status().ToString());
    return;
  }
  v1::Job record;
  if (!record.ParseFromString(stored->record)) {
    spdlog::warn("job {}: stored record is corrupt; its lease runs out", lease.job_id);
    return;
  }
  JobPtr job;
  {
    absl::MutexLock lock(&mu_);
    if (auto it = jobs_.find(lease.job_id); it != jobs_.end()) job = it->second;
  }
  if (job == nullptr) {
    absl::StatusOr<JobPtr> loaded = FromStored(*stored);
    if (!loaded.ok()) return;
    absl::MutexLock lock(&mu_);
    job = jobs_.try_emplace(lease.job_id, *loaded).first->second;
  }

  absl::MutexLock job_lock(&job->mu);
  job->record = std::move(record);
  job->lease = lease;
  job->cancel_cause = CancelCause::kNone;
  job->stop = StopToken();
  job->queued_at = FromProto(job->record.created_at());
  {
    absl::MutexLock lock(&mu_);
    leased_[job->id] = job;
    followed_.erase(job->id);
  }
  if (job->plan.problem.map == nullptr) {  // submitted on another replica
    v1::MapInfo map;
    absl::StatusOr<PlanRequest> plan = Resolve(job->record.request(), job->record.seed(), &map);
    if (!plan.ok()) {
      Finish(*job, v1::JOB_STATE_FAILED, nullptr,
             absl::StrCat("cannot run: ", plan.status().message()));
      return;
    }
    job->plan = std::move(*plan);
  }
  if (!queue_->Push(job, /*ignore_capacity=*/true).ok()) Requeue(*job);
}

void JobManager::KeepLoop() {
  const absl::Duration renew_every = shared_.queue->options().lease / 3;
  absl::Time renewed = absl::Now();
  absl::Time depth_reported = absl::InfinitePast();
  while (!stop_shared_.load()) {
    SleepUnless(stop_shared_, kCancelPoll);
    std::vector<JobPtr> held;
    std::vector<std::string> ids;
    {
      absl::MutexLock lock(&mu_);
      for (const auto& [id, job] : leased_) {
        held.push_back(job);
        ids.push_back(id);
      }
    }
    if (!held.empty()) {
      absl::StatusOr<std::vector<bool>> cancel = shared_.queue->CancelRequested(ids);
      for (size_t i = 0; cancel.ok() && i < held.size(); ++i) {
        if (!(*cancel)[i]) continue;
        absl::MutexLock lock(&held[i]->mu);
        if (!held[i]->lease.has_value() || held[i]->cancel_cause == CancelCause::kClient) continue;
        spdlog::info("job {}: cancelled on another replica; stopping it", held[i]->id);
        held[i]->cancel_cause = CancelCause::kClient;
        if (queue_->Remove(held[i]->id)) {
          Finish(*held[i], v1::JOB_STATE_CANCELLED, nullptr, "cancelled before it started");
        } else {
          held[i]->stop.Cancel();
        }
      }
    }
    const absl::Time now = absl::Now();
    if (now - renewed >= renew_every) {
      renewed = now;
      for (const JobPtr& job : held) {
        absl::MutexLock lock(&job->mu);
        if (!job->lease.has_value()) continue;
        absl::StatusOr<bool> renewal = shared_.queue->Renew(*job->lease);
        if (!renewal.ok()) {
          spdlog::warn("job {}: cannot renew its lease: {}", job->id, renewal.status().ToString());
        } else if (!*renewal) {
          spdlog::warn("job {}: attempt {} was taken over by another replica; it stops here",
                       job->id, job->lease->attempt);
          LoseLease(*job);
        }
      }
    }
    if (now - depth_reported >= kDepthReportEvery) {
      depth_reported = now;
      if (absl::StatusOr<int64_t> waiting = shared_.queue->Waiting(); waiting.ok()) {
        metrics_.SetSharedQueueDepth(*waiting);
      }
    }
  }
}

void JobManager::LoseLease(Job& job) {
  job.lease.reset();
  job.cancel_cause = CancelCause::kLeaseLost;
  job.stop.Cancel();
  queue_->Remove(job.id);  // when no worker started it yet
  absl::MutexLock lock(&mu_);
  if (auto it = leased_.find(job.id); it != leased_.end()) {
    followed_[job.id] = it->second;
    leased_.erase(it);
  }
}

void JobManager::ShareEvent(Job& job, const EventPtr& event) {
  if (event->has_progress()) {
    const absl::Time now = absl::Now();
    if (now - job.progress_shared_at < kShareProgressEvery) {
      job.unshared_progress = event;
      return;
    }
    job.progress_shared_at = now;
  } else if (job.unshared_progress != nullptr) {
    AppendShared(job, *job.unshared_progress);  // the last iteration before a milestone
  }
  job.unshared_progress = nullptr;
  AppendShared(job, *event);
}

void JobManager::AppendShared(Job& job, const v1::JobEvent& event) {
  absl::StatusOr<std::string> entry = shared_.events->Append(event);
  if (!entry.ok()) {
    spdlog::warn("job {}: cannot share an event with other replicas: {}", job.id,
                 entry.status().ToString());
    return;
  }
  job.shared_cursor = *entry;
}

void JobManager::Follow(const JobPtr& job) {
  absl::MutexLock lock(&mu_);
  followed_[job->id] = job;
}

void JobManager::RelayLoop() {
  std::map<std::string, absl::Time> heard;  // when each followed job last had an event
  absl::Time checked = absl::Now();
  while (!stop_shared_.load()) {
    std::vector<JobPtr> all;
    {
      absl::MutexLock lock(&mu_);
      for (const auto& [id, job] : followed_) all.push_back(job);
    }
    std::vector<JobPtr> following;
    std::vector<SharedJobEvents::Cursor> cursors;
    for (const JobPtr& job : all) {
      absl::MutexLock lock(&job->mu);
      if (IsFinal(job->record.state())) {
        absl::MutexLock manager_lock(&mu_);
        followed_.erase(job->id);
        continue;
      }
      if (job->lease.has_value()) continue;  // runs here
      following.push_back(job);
      cursors.push_back({job->id, job->shared_cursor});
    }
    if (cursors.empty()) {
      heard.clear();
      SleepUnless(stop_shared_, kRelayWait);
      continue;
    }
    absl::StatusOr<std::vector<SharedJobEvents::Followed>> read =
        shared_.events->Read(cursors, kRelayWait);
    if (!read.ok()) {
      spdlog::warn("cannot follow the events of jobs on other replicas: {}",
                   read.status().ToString());
      SleepUnless(stop_shared_, kRetryAfterError);
      continue;
    }
    const absl::Time now = absl::Now();
    for (const SharedJobEvents::Followed& followed : *read) {
      auto job = std::find_if(following.begin(), following.end(),
                              [&](const JobPtr& j) { return j->id == followed.job_id; });
      if (job == following.end()) continue;
      heard[followed.job_id] = now;
      ApplyFollowed(*job, followed.entry, followed.event);
    }
    if (now - checked >= kFollowedStoreCheck) {
      checked = now;
      std::vector<JobPtr> quiet;
      std::map<std::string, absl::Time> still_followed;
      for (const JobPtr& job : following) {
        auto it = heard.find(job->id);
        const absl::Time last = it == heard.end() ? absl::InfinitePast() : it->second;
        if (now - last >= kFollowedStoreCheck) quiet.push_back(job);
        still_followed[job->id] = last;
      }
      heard = std::move(still_followed);
      RefreshFollowedFromStore(quiet);
    }
  }
}

void JobManager::ApplyFollowed(const JobPtr& job, const std::string& entry,
                               const v1::JobEvent& event) {
  absl::MutexLock lock(&job->mu);
  if (job->lease.has_value() || IsFinal(job->record.state())) return;
  if (EntryOrder(entry) <= EntryOrder(job->shared_cursor)) return;
  job->shared_cursor = entry;
  v1::Job& record = job->record;
  switch (event.event_case()) {
    case v1::JobEvent::kAccepted:
      record.set_state(v1::JOB_STATE_QUEUED);
      record.set_queue_position(event.accepted().queue_position());
      record.clear_started_at();
      record.clear_progress();
      break;
    case v1::JobEvent::kStarted:
      record.set_state(v1::JOB_STATE_RUNNING);
      record.clear_queue_position();
      *record.mutable_started_at() = event.time();
      record.clear_progress();
      break;
    case v1::JobEvent::kProgress:
      *record.mutable_progress() = event.progress();
      break;
    case v1::JobEvent::kFinished: {
      absl::StatusOr<StoredJob> stored = store_.GetJob(job->id);
      v1::Job final_record;
      if (!stored.ok() || !final_record.ParseFromString(stored->record) ||
          !IsFinal(final_record.state())) {
        // Recorded before the event was shared; when the record cannot be read, the event says
        // the same.
        final_record = record;
        final_record.set_state(event.finished().state());
        *final_record.mutable_finished_at() = event.time();
        if (event.finished().has_result()) {
          *final_record.mutable_result() = event.finished().result();
        }
        final_record.set_failure_reason(event.finished().failure_reason());
      }
      ConcludeFollowed(*job, std::move(final_record));
      return;
    }
    default:
      return;  // requeued events stay on their replica; unreadable entries are skipped
  }
  job->events.Publish(event);
}

void JobManager::ConcludeFollowed(Job& job, v1::Job record) {
  job.record = std::move(record);
  job.events.Publish(FinishedEvent(job.record));
  {
    absl::MutexLock lock(&mu_);
    followed_.erase(job.id);
  }
  Retire(job);
}

void JobManager::RefreshFollowedFromStore(const std::vector<JobPtr>& jobs) {
  for (const JobPtr& job : jobs) {
    absl::StatusOr<StoredJob> stored = store_.GetJob(job->id);
    if (absl::IsNotFound(stored.status())) {
      absl::MutexLock lock(&mu_);
      followed_.erase(job->id);
      continue;
    }
    v1::Job record;
    if (!stored.ok() || !record.ParseFromString(stored->record)) continue;
    absl::MutexLock lock(&job->mu);
    if (job->lease.has_value() || IsFinal(job->record.state())) continue;
    if (IsFinal(record.state())) {
      ConcludeFollowed(*job, std::move(record));
    } else if (record.state() != job->record.state()) {
      // Events were missed (the stream expired, or a replica died before it shared them).
      job->record.set_state(record.state());
      *job->record.mutable_started_at() = record.started_at();
    }
  }
}

absl::Status JobManager::CancelShared(Job& job) {
  v1::Job record =
      FinalRecord(job, v1::JOB_STATE_CANCELLED, nullptr, "cancelled before it started");
  absl::StatusOr<bool> removed = shared_.queue->RemoveWaiting(ToStored(job.id, record));
  if (!removed.ok()) return removed.status();
  if (*removed) {
    {
      absl::MutexLock lock(&mu_);
      followed_.erase(job.id);
    }
    Conclude(job, std::move(record));
    return absl::OkStatus();
  }
  // A replica runs it (or it just finished): ask that one to stop it.
  return shared_.queue->RequestCancel(job.id);
}

absl::StatusOr<std::vector<std::string>> JobManager::SharedJobsOnMap(const std::string& id) {
  absl::StatusOr<std::vector<StoredJob>> unfinished = store_.LoadJobsToRecover();
  if (!unfinished.ok()) return unfinished.status();
  std::vector<std::string> holding;
  for (const StoredJob& stored : *unfinished) {
    v1::Job record;
    if (stored.finished_at != absl::InfiniteFuture() || !record.ParseFromString(stored.record)) {
      continue;
    }
    if (record.request().map_id() == id) holding.push_back(stored.id);
  }
  return holding;
}

void JobManager::ReleaseWaiting() {
  std::vector<JobPtr> held;
  {
    absl::MutexLock lock(&mu_);
    for (const auto& [id, job] : leased_) held.push_back(job);
  }
  for (const JobPtr& job : held) {
    absl::MutexLock lock(&job->mu);
    if (!job->lease.has_value() || IsFinal(job->record.state())) continue;
    job->record.set_state(v1::JOB_STATE_QUEUED);
    job->record.clear_started_at();
    job->record.clear_progress();
    Requeue(*job);
  }
}

}  // namespace swarmplan::server
