#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "absl/status/status.h"

namespace swarmplan::server {

// The server's Prometheus metrics (prometheus-cpp behind a narrow interface). Thread-safe.
//
//   swarmplan_jobs_total{algorithm,state}            jobs finished, by final state
//   swarmplan_job_duration_seconds{algorithm}        planning time of finished jobs
//   swarmplan_job_queue_wait_seconds{algorithm}      time from queued to started
//   swarmplan_job_queue_depth                        jobs waiting
//   swarmplan_workers_busy / swarmplan_workers       workers planning / in the pool
//   swarmplan_fitness_evaluations_total{algorithm}   fitness evaluations of finished jobs
//   swarmplan_rpc_requests_total{method,code}        RPCs handled
//   swarmplan_rpc_duration_seconds{method,code}      RPC latency (streams: until the end)
//   swarmplan_maps_stored                            maps in the store
//   swarmplan_job_cache_entries                      finished jobs held in memory (the rest:
//                                                    in the store only)
//   swarmplan_shared_queue_depth                     jobs waiting in the queue replicas share
//                                                    (a redis:// store only)
//   swarmplan_jobs_reclaimed_total                   jobs this replica took over after another
//                                                    one's lease ran out
//   swarmplan_build_info{version}                    1
class Metrics {
 public:
  Metrics();
  ~Metrics();

  void JobFinished(const std::string& algorithm, const std::string& state, double seconds,
                   int64_t evaluations);
  void JobStarted(const std::string& algorithm, double queue_wait_seconds);
  void SetQueueDepth(int depth);
  void SetWorkers(int total);
  void SetWorkersBusy(int busy);
  void SetMapsStored(int64_t maps);  // ignored when negative (the store could not say)
  void SetJobCacheEntries(int entries);
  void SetSharedQueueDepth(int64_t depth);
  void JobReclaimed();
  void RpcHandled(const std::string& method, const std::string& code, double seconds);

  // Serves GET /metrics on address:port (port 0: any free port). FAILED_PRECONDITION naming
  // the port when it cannot bind.
  absl::Status Serve(const std::string& address, int port);
  // The port /metrics is served on, 0 when not serving.
  int port() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swarmplan::server
