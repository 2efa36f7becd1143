#pragma once

// Shared fixtures of the beetle and swarm planner tests: small maps, a recording observer and
// the checks every planner must pass.

#include <memory>
#include <vector>

#include "core/geometry/collision.h"
#include "core/planner.h"
#include "core/registry.h"
#include "gtest/gtest.h"

namespace swarmplan::beetle_testing {

// Records every iteration; cancels the stop token at `cancel_at` when >= 0.
class RecordingObserver final : public Observer {
 public:
  explicit RecordingObserver(StopToken stop = {}, int cancel_at = -1)
      : stop_(stop), cancel_at_(cancel_at) {}
  void OnIteration(const IterationStats& stats) override {
    stats_.push_back(stats);
    if (stats.iteration == cancel_at_) stop_.Cancel();
  }
  const std::vector<IterationStats>& stats() const { return stats_; }

 private:
  StopToken stop_;
  int cancel_at_;
  std::vector<IterationStats> stats_;
};

inline const Registry& BeetleRegistry() { return DefaultRegistry(); }

inline SearchResult SolveOrDie(const std::string& id, const ParamValues& params,
                               const Problem& problem, Observer& observer,
                               const StopToken& stop = {}) {
  absl::StatusOr<std::unique_ptr<Planner>> planner = BeetleRegistry().Create(id, params);
  EXPECT_TRUE(planner.ok()) << planner.status();
  if (!planner.ok()) return {};
  absl::StatusOr<SearchResult> result = (*planner)->Solve(problem, stop, observer);
  EXPECT_TRUE(result.ok()) << result.status();
  return result.ok() ? *result : SearchResult{};
}

inline double Length(const Path& path) {
  double length = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) length += (path[i + 1] - path[i]).norm();
  return length;
}

// One iteration per OnIteration, numbered from 0, best fitness non-increasing and equal to the
// convergence log of the result.
inline void ExpectWellFormedLog(const SearchResult& result, const RecordingObserver& observer) {
  ASSERT_EQ(static_cast<int>(observer.stats().size()), result.iterations);
  ASSERT_EQ(result.convergence.size(), observer.stats().size());
  for (size_t i = 0; i < observer.stats().size(); ++i) {
    EXPECT_EQ(observer.stats()[i].iteration, static_cast<int>(i));
    EXPECT_EQ(observer.stats()[i].best_fitness, result.convergence[i].best_fitness);
    if (i > 0) {
      EXPECT_LE(observer.stats()[i].best_fitness, observer.stats()[i - 1].best_fitness);
    }
  }
  if (!observer.stats().empty()) {
    EXPECT_EQ(observer.stats().back().best_fitness, result.fitness);
  }
  EXPECT_LE(result.best_iteration, std::max(result.iterations - 1, 0));
}

// The path starts and ends where asked and is collision-free by the map's checker.
inline void ExpectValidPath(const SearchResult& result, const Problem& problem) {
  ASSERT_TRUE(result.found);
  ASSERT_GE(result.path.size(), 2u);
  EXPECT_NEAR((result.path.front() - problem.start).norm(), 0.0, 1e-9);
  EXPECT_NEAR((result.path.back() - problem.goal).norm(), 0.0, 1e-9);
  EXPECT_TRUE(MakeCollisionChecker(*problem.map)->PathFree(result.path, problem.clearance));
}

inline void ExpectSamePath(const SearchResult& a, const SearchResult& b) {
  ASSERT_EQ(a.path.size(), b.path.size());
  for (size_t i = 0; i < a.path.size(); ++i) EXPECT_EQ(a.path[i], b.path[i]) << i;
  EXPECT_EQ(a.fitness, b.fitness);
}

}  // namespace swarmplan::beetle_testing
