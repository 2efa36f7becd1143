#include "core/map/derived_cache.h"

#include <algorithm>

namespace swarmplan {

std::shared_ptr<const void> DerivedCache::GetOrBuild(
    const std::string& key, absl::FunctionRef<std::shared_ptr<const void>()> build) {
  std::shared_ptr<Slot> slot;
  {
    absl::MutexLock lock(&mu_);
    ++clock_;
    auto it = std::find_if(entries_.begin(), entries_.end(),
                           [&](const Entry& e) { return e.key == key; });
    if (it != entries_.end()) {
      it->last_used = clock_;
      slot = it->slot;
    } else {
      if (entries_.size() >= capacity_ && !entries_.empty()) {
        auto oldest = std::min_element(
            entries_.begin(), entries_.end(),
            [](const Entry& a, const Entry& b) { return a.last_used < b.last_used; });
        entries_.erase(oldest);
      }
      slot = std::make_shared<Slot>();
      entries_.push_back(Entry{key, slot, clock_});
    }
  }
  absl::MutexLock lock(&slot->mu);
  if (slot->value == nullptr) {
    slot->value = build();
    absl::MutexLock count(&mu_);
    ++builds_;
  }
  return slot->value;
}

size_t DerivedCache::size() const {
  absl::MutexLock lock(&mu_);
  return entries_.size();
}

int64_t DerivedCache::builds() const {
  absl::MutexLock lock(&mu_);
  return builds_;
}

}  // namespace swarmplan
