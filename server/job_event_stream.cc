#include "server/job_event_stream.h"

#include "absl/base/thread_annotations.h"
#include "absl/synchronization/mutex.h"
#include "server/grpc_status.h"

namespace swarmplan::server {
namespace {

class JobEventStream final : public grpc::ServerWriteReactor<v1::JobEvent> {
 public:
  JobEventStream(JobManager& manager, JobPtr job, int64_t cursor, bool owner)
      : manager_(manager), job_(std::move(job)), owner_(owner), cursor_(cursor) {}

  void Begin(int max_watchers) {
    absl::StatusOr<std::shared_ptr<EventDoorbell>> doorbell =
        job_->events.AddWatcher([this] { Pump(); }, max_watchers);
    if (!doorbell.ok()) {
      {
        absl::MutexLock lock(&mu_);
        finish_called_ = true;
      }
      Finish(ToGrpcStatus(doorbell.status()));
      return;
    }
    {
      absl::MutexLock lock(&mu_);
      doorbell_ = *doorbell;
    }
    Pump();
  }

  void OnWriteDone(bool ok) override {
    {
      absl::MutexLock lock(&mu_);
      writing_ = false;
      if (!ok) broken_ = true;
    }
    Pump();
  }

  void OnCancel() override {
    {
      absl::MutexLock lock(&mu_);
      broken_ = true;
    }
    Pump();
  }

  void OnDone() override {
    std::shared_ptr<EventDoorbell> doorbell;
    {
      absl::MutexLock lock(&mu_);
      doorbell = doorbell_;
    }
    if (doorbell != nullptr) {
      // After RemoveWatcher the doorbell no longer calls Pump: `this` can go.
      const int remaining = job_->events.RemoveWatcher(doorbell);
      manager_.WatcherLeft(job_, owner_, remaining);
    }
    delete this;
  }

 private:
  // Starts the next write, or finishes, unless a write is in flight. Called from any thread.
  void Pump() {
    const v1::JobEvent* write = nullptr;
    grpc::Status finish;
    {
      absl::MutexLock lock(&mu_);
      if (finish_called_ || writing_) return;
      if (broken_) {
        finish_called_ = true;
        finish = grpc::Status(grpc::StatusCode::CANCELLED, "the client went away");
      } else if (sent_final_) {
        finish_called_ = true;
        if (current_->has_requeued()) {
          finish = grpc::Status(grpc::StatusCode::UNAVAILABLE, current_->requeued().reason());
        }
      } else {
        current_ = job_->events.Next(cursor_);
        if (current_ == nullptr) return;
        cursor_ = current_->sequence();
        sent_final_ = IsLastEvent(*current_);
        writing_ = true;
        write = current_.get();
      }
    }
    if (write != nullptr) {
      StartWrite(write);
    } else {
      Finish(finish);
    }
  }

  JobManager& manager_;
  const JobPtr job_;
  const bool owner_;
  absl::Mutex mu_;
  std::shared_ptr<EventDoorbell> doorbell_ ABSL_GUARDED_BY(mu_);
  int64_t cursor_ ABSL_GUARDED_BY(mu_);
  EventPtr current_ ABSL_GUARDED_BY(mu_);  // kept alive while written
  bool writing_ ABSL_GUARDED_BY(mu_) = false;
  bool sent_final_ ABSL_GUARDED_BY(mu_) = false;
  bool broken_ ABSL_GUARDED_BY(mu_) = false;
  bool finish_called_ ABSL_GUARDED_BY(mu_) = false;
};

class FailedStream final : public grpc::ServerWriteReactor<v1::JobEvent> {
 public:
  explicit FailedStream(const grpc::Status& status) { Finish(status); }
  void OnDone() override { delete this; }
};

}  // namespace

grpc::ServerWriteReactor<v1::JobEvent>* StreamJobEvents(JobManager& manager, JobPtr job,
                                                        int64_t cursor, bool owner,
                                                        int max_watchers) {
  auto* stream = new JobEventStream(manager, std::move(job), cursor, owner);
  stream->Begin(max_watchers);
  return stream;
}

grpc::ServerWriteReactor<v1::JobEvent>* FailedJobEventStream(const grpc::Status& status) {
  return new FailedStream(status);
}

}  // namespace swarmplan::server
