#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string_view>

#include "absl/time/clock.h"
#include "absl/time/time.h"

namespace swarmplan {

enum class StopReason { kNone, kCancelled, kDeadline, kIterationCap };

// How many nodes an exact search expands between two looks at its stop token.
inline constexpr int64_t kStopCheckInterval = 4096;
const char* StopReasonName(StopReason reason);

// The rule that ends a planner's search: "cancelled OR past the deadline OR at the iteration
// cap". A small copyable value; copies share the cancellation flag, so any copy can be tripped
// from any thread with Cancel(). Planners call ShouldStop(iteration) once per iteration.
class StopToken {
 public:
  StopToken() : cancelled_(std::make_shared<std::atomic<bool>>(false)) {}

  StopToken WithDeadline(absl::Time deadline) const {
    StopToken t = *this;
    t.deadline_ = std::min(deadline_, deadline);
    return t;
  }
  // 0 means no cap. Iterations are counted from 0; the cap stops before iteration `max`.
  StopToken WithMaxIterations(int max) const {
    StopToken t = *this;
    if (max > 0 && (t.max_iterations_ == 0 || max < t.max_iterations_)) t.max_iterations_ = max;
    return t;
  }

  void Cancel() const { cancelled_->store(true, std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_->load(std::memory_order_relaxed); }
  absl::Time deadline() const { return deadline_; }
  int max_iterations() const { return max_iterations_; }

  // Why the search must stop before running `iteration` (0-based), or kNone.
  StopReason Check(int iteration) const {
    if (cancelled()) return StopReason::kCancelled;
    if (max_iterations_ > 0 && iteration >= max_iterations_) return StopReason::kIterationCap;
    if (deadline_ != absl::InfiniteFuture() && absl::Now() >= deadline_) {
      return StopReason::kDeadline;
    }
    return StopReason::kNone;
  }
  bool ShouldStop(int iteration) const { return Check(iteration) != StopReason::kNone; }

 private:
  std::shared_ptr<std::atomic<bool>> cancelled_;
  absl::Time deadline_ = absl::InfiniteFuture();
  int max_iterations_ = 0;
};

}  // namespace swarmplan
