#pragma once

#include <deque>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "server/job.h"

namespace swarmplan::server {

// A bounded FIFO of jobs in front of a fixed pool of worker threads. Thread-safe.
class JobQueue {
 public:
  using RunFn = std::function<void(const JobPtr&)>;
  // Told the queue depth and the busy workers after every change of either, under the queue's
  // lock (so in order); it must not call back into the queue.
  using LoadFn = std::function<void(int depth, int busy)>;

  JobQueue(int workers, int capacity, RunFn run, LoadFn on_load = nullptr);
  ~JobQueue();  // Stop()
  JobQueue(const JobQueue&) = delete;
  JobQueue& operator=(const JobQueue&) = delete;

  // Queues a job and returns the number of jobs ahead of it. RESOURCE_EXHAUSTED at once when
  // `capacity` jobs are already waiting (unless `ignore_capacity`, for jobs recovered at start);
  // UNAVAILABLE after StopAccepting().
  absl::StatusOr<int> Push(JobPtr job, bool ignore_capacity = false);
  // Takes a job out of the queue; false when it is not waiting (running or unknown).
  bool Remove(const std::string& id);
  // Jobs ahead of `id` in the queue, or -1 when it is not waiting.
  int Position(const std::string& id) const;

  int depth() const;
  int busy() const;
  int workers() const { return static_cast<int>(threads_.size()); }

  // New jobs are refused; workers take no more jobs from the queue; queued jobs stay queued.
  void StopAccepting();
  // Waits until a worker is idle with no job waiting for it; false on timeout or when stopping.
  bool WaitForFreeWorker(absl::Duration timeout);
  // Waits until no worker runs a job; false on timeout.
  bool WaitIdle(absl::Duration timeout);
  // StopAccepting(), then joins the workers after their current job.
  void Stop();

 private:
  void WorkerLoop();
  void ReportLoad() ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);

  const int capacity_;
  const RunFn run_;
  const LoadFn on_load_;
  mutable absl::Mutex mu_;
  std::deque<JobPtr> queue_ ABSL_GUARDED_BY(mu_);
  int busy_ ABSL_GUARDED_BY(mu_) = 0;
  bool stopping_ ABSL_GUARDED_BY(mu_) = false;
  std::vector<std::thread> threads_;
};

}  // namespace swarmplan::server
