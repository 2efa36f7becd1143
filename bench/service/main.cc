// swarmplan-service-bench: what the gRPC service costs and what it must not cost; see
// bench/README.md.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <fstream>
#include <iostream>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "bench/service/measurements.h"
#include "bench/service/service_report.h"

namespace swarmplan::bench {
namespace {

constexpr int kExitBadUsage = 2;

struct Options {
  int repetitions = 15;
  int iterations = 100;
  int jobs = 16;
  int workers = 0;
  int throughput_iterations = 300;
  int watch_iterations = 4000;
  int watch_runs = 3;
  int seed = 7;
  std::string samples = SWARMPLAN_SOURCE_DIR "/samples/maps";
  std::string markdown;
  std::string store;  // a second store to compare with SQLite
  bool store_only = false;
  int max_replicas = 3;
};

PlanCase Bso(const Options& options, int iterations) {
  PlanCase plan;
  plan.map_path = options.samples + "/circles.json";
  plan.algorithm = "bso";
  plan.params = {{"iterations", ParamValue(int64_t{iterations})}};
  plan.start = Point3(5, 5, 0);
  plan.goal = Point3(95, 95, 0);
  plan.seed = static_cast<uint64_t>(options.seed);
  return plan;
}

PlanCase AStar(const Options& options) {
  PlanCase plan;
  plan.map_path = options.samples + "/warehouse.ascii";
  plan.algorithm = "astar";
  plan.start = Point3(2.5, 2.5, 0);  // free cells (2, 2) and (45, 27)
  plan.goal = Point3(45.5, 27.5, 0);
  plan.seed = static_cast<uint64_t>(options.seed);
  return plan;
}

absl::Status MeasureReplicaCounts(const Options& options, ServiceBenchReport& report) {
  const PlanCase plan = Bso(options, options.throughput_iterations);
  report.replicas_plan =
      absl::StrCat("bso (", options.throughput_iterations, " iterations) on circles.json");
  for (int n = 1; n <= options.max_replicas; ++n) {
    std::cerr << "replicas: " << n << "...\n";
    absl::StatusOr<ThroughputResult> r = MeasureReplicas(plan, options.store, n, options.jobs);
    if (!r.ok()) return r.status();
    report.replicas.push_back(*r);
  }
  return absl::OkStatus();
}

absl::Status MeasureStores(const Options& options, ServiceBenchReport& report) {
  for (const PlanCase& plan : {AStar(options), Bso(options, options.iterations)}) {
    std::cerr << "stores: " << plan.algorithm << "...\n";
    absl::StatusOr<StoreLatencyResult> r =
        MeasureStoreLatency(plan, options.store, options.repetitions, options.jobs);
    if (!r.ok()) return r.status();
    if (plan.algorithm == "bso") r->label += absl::StrCat(" (", options.iterations, " iterations)");
    report.stores.push_back(*r);
  }
  return options.max_replicas > 0 ? MeasureReplicaCounts(options, report) : absl::OkStatus();
}

absl::Status Measure(const Options& options, ServiceBenchReport& report) {
  if (options.store_only) return MeasureStores(options, report);
  for (const PlanCase& plan : {AStar(options), Bso(options, options.iterations)}) {
    std::cerr << "overhead: " << plan.algorithm << "...\n";
    absl::StatusOr<OverheadResult> r = MeasureOverhead(plan, options.repetitions);
    if (!r.ok()) return r.status();
    if (plan.algorithm == "bso") r->label += absl::StrCat(" (", options.iterations, " iterations)");
    report.overhead.push_back(*r);
  }

  const PlanCase batch = Bso(options, options.throughput_iterations);
  report.throughput_plan =
      absl::StrCat("bso (", options.throughput_iterations, " iterations) on circles.json");
  const int workers = options.workers > 0 ? options.workers : std::max(report.hardware_cores, 2);
  for (int w : {1, workers}) {
    std::cerr << "throughput: " << w << " worker(s)...\n";
    absl::StatusOr<ThroughputResult> r = MeasureThroughput(batch, w, options.jobs);
    if (!r.ok()) return r.status();
    (w == 1 ? report.one_worker : report.many_workers) = *r;
  }

  const PlanCase long_job = Bso(options, options.watch_iterations);
  report.watcher_plan =
      absl::StrCat("bso (", options.watch_iterations, " iterations) on circles.json");
  for (int run = 0; run < options.watch_runs; ++run) {
    for (bool watched : {false, true}) {
      std::cerr << "watcher: run " << run + 1 << (watched ? ", slow watcher" : ", no watcher")
                << "...\n";
      absl::StatusOr<WatcherResult> r = MeasureWatcher(long_job, watched);
      if (!r.ok()) return r.status();
      (watched ? report.watched : report.unwatched).push_back(*r);
    }
  }
  return options.store.empty() ? absl::OkStatus() : MeasureStores(options, report);
}

int Main(int argc, char** argv) {
  Options options;
  CLI::App app(
      "swarmplan-service-bench: gRPC overhead, worker throughput and slow watchers of "
      "an in-process swarmplan server on 127.0.0.1");
  app.add_option("--repetitions", options.repetitions, "overhead: runs of each path")
      ->check(CLI::Range(1, 10000));
  app.add_option("--iterations", options.iterations, "overhead: bso iterations")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--jobs", options.jobs, "throughput: jobs submitted at once")
      ->check(CLI::Range(1, 10000));
  app.add_option("--workers", options.workers,
                 "throughput: workers of the second server (0: hardware cores, at least 2)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--throughput-iterations", options.throughput_iterations,
                 "throughput: bso iterations per job")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--watch-iterations", options.watch_iterations,
                 "slow watcher: bso iterations of the long job")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--watch-runs", options.watch_runs,
                 "slow watcher: runs with and without the watcher")
      ->check(CLI::Range(1, 100));
  app.add_option("--seed", options.seed, "seed of every plan")->check(CLI::Range(1, 1 << 30));
  app.add_option("--samples", options.samples, "folder holding warehouse.ascii and circles.json");
  app.add_option("--markdown", options.markdown, "also write the report to this file");
  app.add_option("--store", options.store,
                 "also compare the embedded SQLite store with this one (redis://HOST:PORT)");
  app.add_flag("--store-only", options.store_only,
               "measure the stores and the replicas only (needs --store)");
  app.add_option("--max-replicas", options.max_replicas,
                 "with --store: jobs per second with 1..N replicas sharing its queue (0: skip)")
      ->check(CLI::Range(0, 16));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadUsage;
  }
  if (options.store_only && options.store.empty()) {
    std::cerr << "swarmplan-service-bench: --store-only needs --store URL\n";
    return kExitBadUsage;
  }
  spdlog::set_level(spdlog::level::warn);  // the servers' job logs would bury the report

  ServiceBenchReport report;
  report.command = absl::StrJoin(std::vector<std::string>(argv, argv + argc), " ");
  report.hardware_cores = static_cast<int>(std::thread::hardware_concurrency());
  report.seed = options.seed;
  if (absl::Status status = Measure(options, report); !status.ok()) {
    std::cerr << "swarmplan-service-bench: error: " << status << "\n";
    return 1;
  }
  const std::string markdown = ServiceReportMarkdown(report);
  std::cout << markdown;
  if (!options.markdown.empty()) {
    std::ofstream file(options.markdown);
    file << markdown;
    if (!file) {
      std::cerr << "swarmplan-service-bench: error: cannot write " << options.markdown << "\n";
      return 1;
    }
  }
  return 0;
}

}  // namespace
}  // namespace swarmplan::bench

int main(int argc, char** argv) { return swarmplan::bench::Main(argc, argv); }
