#include "server/optimum_cache.h"

namespace swarmplan::server {

OptimumCache::OptimumCache(const Registry& registry, absl::Duration budget, size_t capacity)
    : registry_(registry), budget_(budget), capacity_(capacity) {}

Optimum OptimumCache::Get(const std::string& map_id, const Problem& problem) {
  const Key key{map_id,           problem.start.x(), problem.start.y(), problem.start.z(),
                problem.goal.x(), problem.goal.y(),  problem.goal.z(),  problem.clearance};
  {
    absl::MutexLock lock(&mu_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      ages_.splice(ages_.begin(), ages_, it->second.age);
      return it->second.optimum;
    }
  }
  Optimum optimum = ComputeOptimum(registry_, problem, budget_);
  if (capacity_ == 0) return optimum;
  absl::MutexLock lock(&mu_);
  if (entries_.count(key) > 0) return optimum;
  ages_.push_front(key);
  entries_.emplace(key, Entry{optimum, ages_.begin()});
  while (entries_.size() > capacity_) {
    entries_.erase(ages_.back());
    ages_.pop_back();
  }
  return optimum;
}

size_t OptimumCache::size() const {
  absl::MutexLock lock(&mu_);
  return entries_.size();
}

}  // namespace swarmplan::server
