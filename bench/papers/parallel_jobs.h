#pragma once

// Independent runs of an experiment on several threads. Each job writes only its own result,
// and a run's outcome depends on its seed alone, so a report is the same for any thread count.

#include <functional>
#include <mutex>
#include <ostream>
#include <string>

#include "absl/status/status.h"

namespace swarmplan::bench {

// Runs job(0), ..., job(count - 1) on min(threads, count) threads (at least one). Every job
// runs; the error of the lowest-numbered failed job is returned.
absl::Status RunJobs(int count, int threads, const std::function<absl::Status(int)>& job);

// Progress lines from several threads, each written whole; a null stream discards them.
class ProgressLog {
 public:
  explicit ProgressLog(std::ostream* out) : out_(out) {}
  void Line(const std::string& line);

 private:
  std::ostream* out_;
  std::mutex mutex_;
};

}  // namespace swarmplan::bench
