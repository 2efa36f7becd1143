#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/service/plan_case.h"

namespace swarmplan::bench {

// 1. The same plan in-process (core RunPlan) and through a 1-worker server: a Plan stream read
// to its end, and SubmitPlan then GetJob polled every millisecond.
struct OverheadResult {
  std::string label;  // "astar on warehouse.ascii"
  int repetitions = 0;
  double in_process_seconds = 0;  // medians of client-side wall time
  double plan_stream_seconds = 0;
  double submit_get_seconds = 0;
  bool identical = false;  // every served result equals the in-process one
  std::string difference;  // the first difference when not identical
};
absl::StatusOr<OverheadResult> MeasureOverhead(const PlanCase& plan, int repetitions);

// 2. `jobs` copies of a plan submitted at once to a server with `workers` workers; the time
// from the first submission until every job is final.
struct ThroughputResult {
  int workers = 0;
  int jobs = 0;
  double seconds = 0;
  int succeeded = 0;
  double jobs_per_second() const { return seconds > 0 ? jobs / seconds : 0; }
};
absl::StatusOr<ThroughputResult> MeasureThroughput(const PlanCase& plan, int workers, int jobs);

// 3. A long job reporting progress every iteration, with nobody watching (GetJob polled every
// 100 ms) or with a watcher that reads one event per second while the job runs (then the rest of
// its stream at once). The rate is the job's iterations over its wall time as the server
// measured it.
struct WatcherResult {
  bool slow_watcher = false;
  int iterations = 0;
  double planner_seconds = 0;
  int progress_events = 0;  // progress events the watcher received in all (0 without one)
  int events = 0;           // all events the watcher received
  int slow_reads = 0;       // events it read (one per second) while the job ran
  double iterations_per_second() const {
    return planner_seconds > 0 ? iterations / planner_seconds : 0;
  }
};
absl::StatusOr<WatcherResult> MeasureWatcher(const PlanCase& plan, bool slow_watcher);

// 4. The same plan through two 1-worker servers, one on the embedded SQLite store and one on
// `store` (for example redis://127.0.0.1:6379), interleaved: a Plan stream read to its end,
// `repetitions` times, and `batch_jobs` copies submitted at once until all are final, 3 times.
struct StoreLatencyResult {
  std::string store;
  std::string label;
  int repetitions = 0;
  int batch_jobs = 0;
  double sqlite_plan_seconds = 0;  // medians of client-side wall time
  double store_plan_seconds = 0;
  double sqlite_batch_seconds = 0;
  double store_batch_seconds = 0;
};
absl::StatusOr<StoreLatencyResult> MeasureStoreLatency(const PlanCase& plan,
                                                       const std::string& store, int repetitions,
                                                       int batch_jobs);

// 5. `jobs` copies of a plan submitted round-robin to `replicas` servers of 1 worker each on one
// shared store (redis://...), which run them from its shared queue; the time from the first
// submission until every job is final. `workers` of the result is the number of replicas.
absl::StatusOr<ThroughputResult> MeasureReplicas(const PlanCase& plan, const std::string& store,
                                                 int replicas, int jobs);

}  // namespace swarmplan::bench
