#include "server/metrics.h"

#include <prometheus/counter.h>
#include <prometheus/exposer.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>
#include <prometheus/registry.h>

#include <map>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/synchronization/mutex.h"

#ifndef SWARMPLAN_VERSION
#define SWARMPLAN_VERSION "unknown"
#endif

namespace swarmplan::server {
namespace {

using Labels = std::map<std::string, std::string>;

const prometheus::Histogram::BucketBoundaries& TimeBuckets() {
  static const auto* buckets = new prometheus::Histogram::BucketBoundaries{
      0.001, 0.005, 0.01, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10, 30, 60, 300, 600};
  return *buckets;
}

// Family::Add is slow: cache the metric of each label set.
template <typename M>
class Cached {
 public:
  explicit Cached(prometheus::Family<M>& family) : family_(family) {}
  template <typename... Args>
  M& Get(const Labels& labels, Args&&... args) {
    absl::MutexLock lock(&mu_);
    auto it = cache_.find(labels);
    if (it == cache_.end()) {
      it = cache_.emplace(labels, &family_.Add(labels, std::forward<Args>(args)...)).first;
    }
    return *it->second;
  }

 private:
  prometheus::Family<M>& family_;
  absl::Mutex mu_;
  std::map<Labels, M*> cache_;
};

}  // namespace

struct Metrics::Impl {
  std::shared_ptr<prometheus::Registry> registry = std::make_shared<prometheus::Registry>();
  Cached<prometheus::Counter> jobs{prometheus::BuildCounter()
                                       .Name("swarmplan_jobs_total")
                                       .Help("Jobs finished, by algorithm and final state")
                                       .Register(*registry)};
  Cached<prometheus::Histogram> duration{prometheus::BuildHistogram()
                                             .Name("swarmplan_job_duration_seconds")
                                             .Help("Planning time of finished jobs")
                                             .Register(*registry)};
  Cached<prometheus::Histogram> queue_wait{
      prometheus::BuildHistogram()
          .Name("swarmplan_job_queue_wait_seconds")
          .Help("Time jobs waited in the queue before a worker took them, by algorithm")
          .Register(*registry)};
  prometheus::Gauge& queue_depth = prometheus::BuildGauge()
                                       .Name("swarmplan_job_queue_depth")
                                       .Help("Jobs waiting for a worker")
                                       .Register(*registry)
                                       .Add({});
  prometheus::Gauge& busy = prometheus::BuildGauge()
                                .Name("swarmplan_workers_busy")
                                .Help("Workers running a job")
                                .Register(*registry)
                                .Add({});
  prometheus::Gauge& workers = prometheus::BuildGauge()
                                   .Name("swarmplan_workers")
                                   .Help("Workers in the pool")
                                   .Register(*registry)
                                   .Add({});
  Cached<prometheus::Counter> evaluations{prometheus::BuildCounter()
                                              .Name("swarmplan_fitness_evaluations_total")
                                              .Help("Fitness evaluations of finished jobs")
                                              .Register(*registry)};
  Cached<prometheus::Counter> rpcs{prometheus::BuildCounter()
                                       .Name("swarmplan_rpc_requests_total")
                                       .Help("RPCs handled, by method and status code")
                                       .Register(*registry)};
  Cached<prometheus::Histogram> rpc_duration{
      prometheus::BuildHistogram()
          .Name("swarmplan_rpc_duration_seconds")
          .Help("RPC latency by method and status code (streams: until their end)")
          .Register(*registry)};
  prometheus::Gauge& maps = prometheus::BuildGauge()
                                .Name("swarmplan_maps_stored")
                                .Help("Maps in the store")
                                .Register(*registry)
                                .Add({});
  prometheus::Gauge& job_cache = prometheus::BuildGauge()
                                     .Name("swarmplan_job_cache_entries")
                                     .Help(
                                         "Finished jobs held in memory; the others are read "
                                         "from the store when asked for")
                                     .Register(*registry)
                                     .Add({});
  prometheus::Gauge& shared_queue_depth =
      prometheus::BuildGauge()
          .Name("swarmplan_shared_queue_depth")
          .Help("Jobs waiting in the queue the replicas on one Redis share")
          .Register(*registry)
          .Add({});
  prometheus::Counter& reclaimed =
      prometheus::BuildCounter()
          .Name("swarmplan_jobs_reclaimed_total")
          .Help("Jobs this replica took over after the lease of another replica ran out")
          .Register(*registry)
          .Add({});
  std::unique_ptr<prometheus::Exposer> exposer;
  int port = 0;

  Impl() {
    prometheus::BuildGauge()
        .Name("swarmplan_build_info")
        .Help("Build information; always 1")
        .Register(*registry)
        .Add({{"version", SWARMPLAN_VERSION}})
        .Set(1);
  }
};

Metrics::Metrics() : impl_(std::make_unique<Impl>()) {}
Metrics::~Metrics() = default;

void Metrics::JobFinished(const std::string& algorithm, const std::string& state, double seconds,
                          int64_t evaluations) {
  impl_->jobs.Get({{"algorithm", algorithm}, {"state", state}}).Increment();
  impl_->duration.Get({{"algorithm", algorithm}}, TimeBuckets()).Observe(seconds);
  impl_->evaluations.Get({{"algorithm", algorithm}}).Increment(static_cast<double>(evaluations));
}

void Metrics::JobStarted(const std::string& algorithm, double queue_wait_seconds) {
  impl_->queue_wait.Get({{"algorithm", algorithm}}, TimeBuckets()).Observe(queue_wait_seconds);
}

void Metrics::SetQueueDepth(int depth) { impl_->queue_depth.Set(depth); }

void Metrics::SetWorkers(int total) { impl_->workers.Set(total); }

void Metrics::SetWorkersBusy(int busy) { impl_->busy.Set(busy); }

void Metrics::SetSharedQueueDepth(int64_t depth) {
  impl_->shared_queue_depth.Set(static_cast<double>(depth));
}

void Metrics::JobReclaimed() { impl_->reclaimed.Increment(); }

void Metrics::SetMapsStored(int64_t maps) {
  if (maps >= 0) impl_->maps.Set(static_cast<double>(maps));
}

void Metrics::SetJobCacheEntries(int entries) { impl_->job_cache.Set(entries); }

void Metrics::RpcHandled(const std::string& method, const std::string& code, double seconds) {
  const Labels labels{{"method", method}, {"code", code}};
  impl_->rpcs.Get(labels).Increment();
  impl_->rpc_duration.Get(labels, TimeBuckets()).Observe(seconds);
}

absl::Status Metrics::Serve(const std::string& address, int port) {
  try {
    impl_->exposer = std::make_unique<prometheus::Exposer>(absl::StrCat(address, ":", port), 2);
    impl_->exposer->RegisterCollectable(impl_->registry);
    const std::vector<int> ports = impl_->exposer->GetListeningPorts();
    impl_->port = ports.empty() ? port : ports.front();
  } catch (const std::exception& e) {
    return absl::FailedPreconditionError(
        absl::StrCat("--metrics-port ", port, ": cannot serve metrics on ", address, ":", port,
                     " (", e.what(), "); choose another port or 0 to disable"));
  }
  return absl::OkStatus();
}

int Metrics::port() const { return impl_->port; }

}  // namespace swarmplan::server
