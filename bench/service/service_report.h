#pragma once

#include <string>
#include <vector>

#include "bench/service/measurements.h"

namespace swarmplan::bench {

// Everything one run of swarmplan-service-bench measured, and how.
struct ServiceBenchReport {
  std::string command;
  int hardware_cores = 0;
  int seed = 0;
  std::vector<OverheadResult> overhead;
  std::string throughput_plan;  // e.g. "bso (300 iterations) on circles.json"
  ThroughputResult one_worker;
  ThroughputResult many_workers;
  std::string watcher_plan;
  std::vector<WatcherResult> unwatched;  // one per run
  std::vector<WatcherResult> watched;
  std::vector<StoreLatencyResult> stores;  // with --store only
  std::string replicas_plan;               // with --store only
  std::vector<ThroughputResult> replicas;  // 1, 2, ... replicas (workers: the replicas)
};

std::string ServiceReportMarkdown(const ServiceBenchReport& report);

}  // namespace swarmplan::bench
