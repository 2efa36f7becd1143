#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/functional/function_ref.h"
#include "absl/synchronization/mutex.h"

namespace swarmplan {

// Structures derived from one immutable map (corner sets, clearance grids, grown obstacles),
// built lazily on first use and shared by every job on that map. Thread-safe. Each key is
// built at most once while it stays cached: concurrent callers of the same key wait for the
// one build, callers of other keys never wait for it. At most `capacity` keys are kept; the
// least recently used is evicted (its value lives on while callers still hold it), because
// keys may include client-chosen values such as a clearance.
class DerivedCache {
 public:
  static constexpr size_t kDefaultCapacity = 16;

  explicit DerivedCache(size_t capacity = kDefaultCapacity) : capacity_(capacity) {}
  DerivedCache(const DerivedCache&) = delete;
  DerivedCache& operator=(const DerivedCache&) = delete;

  // The value cached under `key`, built by `build` when absent. `build` runs without the
  // cache's lock (only the key's own lock is held) and must not call back into this cache
  // with the same key.
  std::shared_ptr<const void> GetOrBuild(const std::string& key,
                                         absl::FunctionRef<std::shared_ptr<const void>()> build);

  size_t size() const;
  size_t capacity() const { return capacity_; }
  // How many builds ran since construction (for tests and diagnostics).
  int64_t builds() const;

 private:
  struct Slot {
    absl::Mutex mu;
    std::shared_ptr<const void> value ABSL_GUARDED_BY(mu);
  };
  struct Entry {
    std::string key;
    std::shared_ptr<Slot> slot;
    uint64_t last_used = 0;
  };

  const size_t capacity_;
  mutable absl::Mutex mu_;
  std::vector<Entry> entries_ ABSL_GUARDED_BY(mu_);
  uint64_t clock_ ABSL_GUARDED_BY(mu_) = 0;
  int64_t builds_ ABSL_GUARDED_BY(mu_) = 0;
};

}  // namespace swarmplan
