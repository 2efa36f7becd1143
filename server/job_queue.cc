#include "server/job_queue.h"

#include <algorithm>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"

namespace swarmplan::server {

JobQueue::JobQueue(int workers, int capacity, RunFn run, LoadFn on_load)
    : capacity_(capacity), run_(std::move(run)), on_load_(std::move(on_load)) {
  for (int i = 0; i < std::max(workers, 1); ++i) threads_.emplace_back([this] { WorkerLoop(); });
}

JobQueue::~JobQueue() { Stop(); }

absl::StatusOr<int> JobQueue::Push(JobPtr job, bool ignore_capacity) {
  absl::MutexLock lock(&mu_);
  if (stopping_) return absl::UnavailableError("the server is shutting down");
  if (!ignore_capacity && static_cast<int>(queue_.size()) >= capacity_) {
    return absl::ResourceExhaustedError(
        absl::StrCat("the job queue is full (", capacity_, " jobs waiting, ", busy_,
                     " running); retry later or raise --queue-capacity"));
  }
  queue_.push_back(std::move(job));
  ReportLoad();
  return static_cast<int>(queue_.size()) - 1;
}

bool JobQueue::Remove(const std::string& id) {
  absl::MutexLock lock(&mu_);
  auto it =
      std::find_if(queue_.begin(), queue_.end(), [&](const JobPtr& j) { return j->id == id; });
  if (it == queue_.end()) return false;
  queue_.erase(it);
  ReportLoad();
  return true;
}

int JobQueue::Position(const std::string& id) const {
  absl::MutexLock lock(&mu_);
  for (size_t i = 0; i < queue_.size(); ++i) {
    if (queue_[i]->id == id) return static_cast<int>(i);
  }
  return -1;
}

int JobQueue::depth() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(queue_.size());
}

int JobQueue::busy() const {
  absl::MutexLock lock(&mu_);
  return busy_;
}

void JobQueue::StopAccepting() {
  absl::MutexLock lock(&mu_);
  stopping_ = true;
}

bool JobQueue::WaitIdle(absl::Duration timeout) {
  absl::MutexLock lock(&mu_);
  auto idle = [this]() ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) { return busy_ == 0; };
  return mu_.AwaitWithTimeout(absl::Condition(&idle), timeout);
}

bool JobQueue::WaitForFreeWorker(absl::Duration timeout) {
  absl::MutexLock lock(&mu_);
  auto free = [this]() ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) {
    return stopping_ || busy_ + static_cast<int>(queue_.size()) < workers();
  };
  return mu_.AwaitWithTimeout(absl::Condition(&free), timeout) && !stopping_;
}

void JobQueue::Stop() {
  StopAccepting();
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
}

void JobQueue::WorkerLoop() {
  while (true) {
    JobPtr job;
    {
      absl::MutexLock lock(&mu_);
      auto ready = [this]()
                       ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_) { return stopping_ || !queue_.empty(); };
      mu_.Await(absl::Condition(&ready));
      if (stopping_) return;
      job = std::move(queue_.front());
      queue_.pop_front();
      ++busy_;
      ReportLoad();
    }
    run_(job);
    absl::MutexLock lock(&mu_);
    --busy_;
    ReportLoad();
  }
}

void JobQueue::ReportLoad() {
  if (on_load_) on_load_(static_cast<int>(queue_.size()), busy_);
}

}  // namespace swarmplan::server
