#pragma once

#include <cstddef>
#include <list>
#include <string>
#include <tuple>
#include <unordered_map>

#include "absl/base/thread_annotations.h"
#include "absl/hash/hash.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "core/optimum.h"
#include "core/problem.h"
#include "core/registry.h"

namespace swarmplan::server {

// The exact optimum of each (map, start, goal, clearance) a job planned, computed once within a
// time budget and kept for later jobs on the same query. Bounded: the least recently used entry
// goes first. Thread-safe; two workers asking for the same new query may both compute it.
class OptimumCache {
 public:
  OptimumCache(const Registry& registry, absl::Duration budget, size_t capacity);

  // The optimum for `problem` on the stored map `map_id`.
  Optimum Get(const std::string& map_id, const Problem& problem);

  size_t size() const;

 private:
  using Key = std::tuple<std::string, double, double, double, double, double, double, double>;
  struct Entry {
    Optimum optimum;
    std::list<Key>::iterator age;
  };

  const Registry& registry_;
  const absl::Duration budget_;
  const size_t capacity_;
  mutable absl::Mutex mu_;
  std::list<Key> ages_ ABSL_GUARDED_BY(mu_);  // most recently used first
  std::unordered_map<Key, Entry, absl::Hash<Key>> entries_ ABSL_GUARDED_BY(mu_);
};

}  // namespace swarmplan::server
