#include "bench/papers/parallel_jobs.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace swarmplan::bench {

absl::Status RunJobs(int count, int threads, const std::function<absl::Status(int)>& job) {
  std::vector<absl::Status> statuses(std::max(count, 0));
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i = next++; i < count; i = next++) statuses[i] = job(i);
  };
  const int workers = std::clamp(threads, 1, std::max(count, 1));
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  for (const absl::Status& status : statuses) {
    if (!status.ok()) return status;
  }
  return absl::OkStatus();
}

void ProgressLog::Line(const std::string& line) {
  if (out_ == nullptr) return;
  std::lock_guard<std::mutex> lock(mutex_);
  *out_ << line << "\n";
}

}  // namespace swarmplan::bench
