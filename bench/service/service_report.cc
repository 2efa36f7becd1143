#include "bench/service/service_report.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/statistics.h"

namespace swarmplan::bench {
namespace {

std::string Ratio(double numerator, double denominator) {
  return denominator > 0 ? absl::StrFormat("%.2f", numerator / denominator) : "–";
}

std::string Millis(double seconds) { return absl::StrFormat("%.3f", seconds * 1000); }

double MedianRate(const std::vector<WatcherResult>& runs) {
  std::vector<double> rates;
  for (const WatcherResult& run : runs) rates.push_back(run.iterations_per_second());
  return Median(rates).value_or(0);
}

void AppendOverhead(const ServiceBenchReport& report, std::string& md) {
  absl::StrAppend(&md, "## 1. gRPC overhead: the same plan in-process and through the server\n\n",
                  "Seed ", report.seed,
                  "; server with 1 worker on 127.0.0.1; client-side wall time, median of the "
                  "repetitions (after one untimed call of each path). `Plan` reads the stream to "
                  "its end; `SubmitPlan+GetJob` polls GetJob every millisecond.\n\n",
                  "| plan | reps | in-process ms | Plan stream ms | SubmitPlan+GetJob ms | "
                  "Plan / in-process | Submit+Get / in-process | same result |\n",
                  "|---|---:|---:|---:|---:|---:|---:|---|\n");
  for (const OverheadResult& r : report.overhead) {
    absl::StrAppend(&md, "| ", r.label, " | ", r.repetitions, " | ", Millis(r.in_process_seconds),
                    " | ", Millis(r.plan_stream_seconds), " | ", Millis(r.submit_get_seconds),
                    " | ", Ratio(r.plan_stream_seconds, r.in_process_seconds), " | ",
                    Ratio(r.submit_get_seconds, r.in_process_seconds), " | ",
                    r.identical ? "identical" : absl::StrCat("**differs**: ", r.difference),
                    " |\n");
  }
  absl::StrAppend(&md,
                  "\n\"identical\": every served result (both paths, every repetition) has the "
                  "in-process run's path point for point, fitness, iterations, evaluations and "
                  "seed.\n\n");
}

void AppendThroughput(const ServiceBenchReport& report, std::string& md) {
  const ThroughputResult& one = report.one_worker;
  const ThroughputResult& many = report.many_workers;
  absl::StrAppend(&md, "## 2. Throughput: 1 worker vs ", many.workers, " workers\n\n", one.jobs,
                  " jobs of ", report.throughput_plan,
                  " submitted at once with SubmitPlan; time until all are final.\n\n",
                  "| workers | jobs | seconds | jobs/s |\n|---:|---:|---:|---:|\n");
  for (const ThroughputResult* r : {&one, &many}) {
    absl::StrAppend(&md, "| ", r->workers, " | ", r->jobs, " | ",
                    absl::StrFormat("%.3f", r->seconds), " | ",
                    absl::StrFormat("%.2f", r->jobs_per_second()), " |\n");
  }
  absl::StrAppend(&md, "\nSpeed-up ", many.workers, " workers / 1 worker: **",
                  Ratio(many.jobs_per_second(), one.jobs_per_second()), "** (ideal ", many.workers,
                  " on ", many.workers, " idle cores).\n\n");
}

void AppendWatcher(const ServiceBenchReport& report, std::string& md) {
  absl::StrAppend(&md, "## 3. A slow watcher does not slow the planner\n\n", report.watcher_plan,
                  ", progress every iteration, 1 worker. Without a watcher the client polls "
                  "GetJob every 100 ms; with one, a WatchJob stream is read one event per second "
                  "while the job runs, then the rest of the stream (what gRPC had buffered) at "
                  "once. "
                  "Rate = the job's iterations / its wall time as the server measured it.\n\n",
                  "| run | watcher | iterations | planner s | iterations/s | reads while running | "
                  "events received | progress events received |\n"
                  "|---:|---|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < report.unwatched.size() || i < report.watched.size(); ++i) {
    for (const std::vector<WatcherResult>* runs : {&report.unwatched, &report.watched}) {
      if (i >= runs->size()) continue;
      const WatcherResult& r = (*runs)[i];
      absl::StrAppend(&md, "| ", i + 1, " | ", r.slow_watcher ? "1 event/s" : "none", " | ",
                      r.iterations, " | ", absl::StrFormat("%.3f", r.planner_seconds), " | ",
                      absl::StrFormat("%.1f", r.iterations_per_second()), " | ",
                      r.slow_watcher ? absl::StrCat(r.slow_reads) : "–", " | ",
                      r.slow_watcher ? absl::StrCat(r.events) : "–", " | ",
                      r.slow_watcher ? absl::StrCat(r.progress_events) : "–", " |\n");
    }
  }
  const double unwatched = MedianRate(report.unwatched);
  const double watched = MedianRate(report.watched);
  absl::StrAppend(&md, "\nMedian iterations/s: ", absl::StrFormat("%.1f", unwatched),
                  " without a watcher, ", absl::StrFormat("%.1f", watched),
                  " with the slow watcher; ratio with / without: **", Ratio(watched, unwatched),
                  "** (1 = no slow-down).\n");
  if (!report.watched.empty()) {
    const WatcherResult& r = report.watched.front();
    absl::StrAppend(&md, "The slow watcher of run 1 received ", r.progress_events,
                    " progress events in all for ", r.iterations,
                    " iterations published, of which it read ", r.slow_reads,
                    " while the job ran. The server never waits for a watcher: events the "
                    "client has not read are buffered by gRPC (flow-control window) and, once "
                    "that is full, coalesced by the server (the latest progress wins), so "
                    "fewer progress events than iterations means coalescing happened.\n");
  }
}

void AppendStores(const ServiceBenchReport& report, std::string& md) {
  if (report.stores.empty()) return;
  const StoreLatencyResult& first = report.stores.front();
  absl::StrAppend(&md, "## 4. Stores: embedded SQLite against `", first.store, "`\n\n",
                  "Two servers with 1 worker each on 127.0.0.1, one per store, called in turn. "
                  "`Plan`: client-side wall time of a Plan stream read to its end, median of ",
                  first.repetitions, " calls; batch: ", first.batch_jobs,
                  " jobs submitted at once until all are final (GetJob polled every "
                  "millisecond), median of 3.\n\n",
                  "| plan | SQLite Plan ms | other Plan ms | other / SQLite | SQLite batch s | "
                  "other batch s | other / SQLite |\n|---|---:|---:|---:|---:|---:|---:|\n");
  for (const StoreLatencyResult& r : report.stores) {
    absl::StrAppend(&md, "| ", r.label, " | ", Millis(r.sqlite_plan_seconds), " | ",
                    Millis(r.store_plan_seconds), " | ",
                    Ratio(r.store_plan_seconds, r.sqlite_plan_seconds), " | ",
                    absl::StrFormat("%.3f", r.sqlite_batch_seconds), " | ",
                    absl::StrFormat("%.3f", r.store_batch_seconds), " | ",
                    Ratio(r.store_batch_seconds, r.sqlite_batch_seconds), " |\n");
  }
  absl::StrAppend(&md, "\n");
}

void AppendReplicas(const ServiceBenchReport& report, std::string& md) {
  if (report.replicas.empty()) return;
  const ThroughputResult& one = report.replicas.front();
  absl::StrAppend(&md, "## 5. Replicas on one shared queue\n\n", one.jobs, " jobs of ",
                  report.replicas_plan,
                  " submitted round-robin to servers of 1 worker each on one Redis, until all "
                  "are final.\n\n| replicas | seconds | jobs/s | jobs/s over 1 replica |\n"
                  "|---:|---:|---:|---:|\n");
  for (const ThroughputResult& r : report.replicas) {
    absl::StrAppend(&md, "| ", r.workers, " | ", absl::StrFormat("%.3f", r.seconds), " | ",
                    absl::StrFormat("%.2f", r.jobs_per_second()), " | ",
                    Ratio(r.jobs_per_second(), one.jobs_per_second()), " |\n");
  }
  absl::StrAppend(&md, "\n");
}

}  // namespace

std::string ServiceReportMarkdown(const ServiceBenchReport& report) {
  std::string md = absl::StrCat("# swarmplan-service-bench\n\n", "Command: `", report.command,
                                "`  \nHardware cores: ", report.hardware_cores,
                                ". Absolute times depend on the machine and its load; the "
                                "ratios are the meaningful figures.\n\n");
  if (!report.overhead.empty()) AppendOverhead(report, md);
  if (report.one_worker.jobs > 0) AppendThroughput(report, md);
  if (!report.unwatched.empty()) AppendWatcher(report, md);
  AppendStores(report, md);
  AppendReplicas(report, md);
  return md;
}

}  // namespace swarmplan::bench
