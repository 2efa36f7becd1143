// Measurement 3: a slow watcher must not slow the planner.
#include <atomic>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "bench/service/bench_server.h"
#include "bench/service/measurements.h"
#include "server/proto_convert.h"

namespace swarmplan::bench {
namespace {

constexpr absl::Duration kGiveUp = absl::Minutes(10);
// A bound on the watcher's loop (the job publishes at most one event per iteration).
constexpr int kMaxWatcherReads = 10000000;

struct WatchCount {
  int events = 0;
  int progress_events = 0;
  int slow_reads = 0;  // events read while the job ran
  absl::Status status;
};

// Reads one event, then sleeps a second, while the job runs; once `job_done`, reads the rest
// of the stream (what gRPC had buffered) without sleeping.
WatchCount WatchSlowly(v1::JobService::Stub& jobs, const std::string& id,
                       const std::atomic<bool>& job_done) {
  WatchCount count;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + absl::ToChronoSeconds(kGiveUp));
  v1::WatchJobRequest request;
  request.set_id(id);
  std::unique_ptr<grpc::ClientReader<v1::JobEvent>> reader = jobs.WatchJob(&context, request);
  v1::JobEvent event;
  bool finished = false;
  while (!finished && count.events < kMaxWatcherReads && reader->Read(&event)) {
    ++count.events;
    if (event.has_progress()) ++count.progress_events;
    finished = event.has_finished();
    if (!finished && !job_done.load()) {
      ++count.slow_reads;
      absl::SleepFor(absl::Seconds(1));
    }
  }
  if (!finished) context.TryCancel();
  grpc::Status status = reader->Finish();
  if (!finished) {
    count.status = status.ok() ? absl::InternalError("WatchJob ended before the job finished")
                               : FromGrpc("WatchJob", status);
  }
  return count;
}

}  // namespace

absl::StatusOr<WatcherResult> MeasureWatcher(const PlanCase& plan, bool slow_watcher) {
  absl::StatusOr<std::unique_ptr<BenchServer>> server = BenchServer::Start(1, 4);
  if (!server.ok()) return server.status();
  absl::StatusOr<std::string> map_id = (*server)->UploadMapFile(plan.map_path);
  if (!map_id.ok()) return map_id.status();

  absl::StatusOr<v1::Job> job = (*server)->Submit(ToProtoRequest(plan, *map_id, 1));
  if (!job.ok()) return job.status();
  WatchCount count;
  std::atomic<bool> job_done{false};
  std::thread watcher;
  if (slow_watcher) {
    watcher = std::thread([&] { count = WatchSlowly((*server)->jobs(), job->id(), job_done); });
  }
  job = (*server)->WaitUntilFinal(job->id(), absl::Milliseconds(100), kGiveUp);
  job_done.store(true);
  if (watcher.joinable()) watcher.join();
  if (!job.ok()) return job.status();
  if (!count.status.ok()) return count.status;
  if (!job->has_result()) {
    return absl::InternalError(absl::StrCat("watcher job ended as ",
                                            v1::JobState_Name(job->state()),
                                            " without a result: ", job->failure_reason()));
  }
  WatcherResult out;
  out.slow_watcher = slow_watcher;
  out.iterations = job->result().iterations();
  out.planner_seconds = absl::ToDoubleSeconds(server::FromProto(job->result().wall_time()));
  out.events = count.events;
  out.progress_events = count.progress_events;
  out.slow_reads = count.slow_reads;
  return out;
}

}  // namespace swarmplan::bench
