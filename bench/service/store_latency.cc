// Measurement 4: what the store costs a plan: the same plans through a server on the embedded
// SQLite store and through one on another store (Redis), interleaved so that both see the same
// machine load.
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "bench/service/bench_server.h"
#include "bench/service/measurements.h"
#include "bench/statistics.h"

namespace swarmplan::bench {
namespace {

constexpr absl::Duration kGiveUp = absl::Minutes(5);

// The time until `jobs` copies of `request`, submitted at once, are all final.
absl::StatusOr<double> TimeBatch(BenchServer& server, const v1::PlanRequest& request, int jobs) {
  const absl::Time start = absl::Now();
  std::vector<std::string> ids;
  for (int j = 0; j < jobs; ++j) {
    absl::StatusOr<v1::Job> job = server.Submit(request);
    if (!job.ok()) return job.status();
    ids.push_back(job->id());
  }
  for (const std::string& id : ids) {
    absl::StatusOr<v1::Job> job = server.WaitUntilFinal(id, absl::Milliseconds(1), kGiveUp);
    if (!job.ok()) return job.status();
    if (job->state() != v1::JOB_STATE_SUCCEEDED) {
      return absl::InternalError(
          absl::StrCat("store batch job ", id, " ended as ", v1::JobState_Name(job->state())));
    }
  }
  return absl::ToDoubleSeconds(absl::Now() - start);
}

}  // namespace

absl::StatusOr<StoreLatencyResult> MeasureStoreLatency(const PlanCase& plan,
                                                       const std::string& store, int repetitions,
                                                       int batch_jobs) {
  StoreLatencyResult out;
  out.store = store;
  out.label = absl::StrCat(plan.algorithm, " on ",
                           std::filesystem::path(plan.map_path).filename().string());
  out.repetitions = repetitions;
  out.batch_jobs = batch_jobs;
  absl::StatusOr<std::unique_ptr<BenchServer>> sqlite = BenchServer::Start(1, batch_jobs);
  if (!sqlite.ok()) return sqlite.status();
  absl::StatusOr<std::unique_ptr<BenchServer>> other = BenchServer::Start(1, batch_jobs, store);
  if (!other.ok()) return other.status();
  BenchServer* servers[2] = {sqlite->get(), other->get()};
  v1::PlanRequest requests[2];
  std::vector<double> plan_seconds[2], batch_seconds[2];
  for (int s = 0; s < 2; ++s) {
    absl::StatusOr<std::string> map_id = servers[s]->UploadMapFile(plan.map_path);
    if (!map_id.ok()) return map_id.status();
    requests[s] = ToProtoRequest(plan, *map_id);
    // One untimed call first: connection set-up and the first parse of the map.
    if (absl::StatusOr<v1::PlanResult> r = servers[s]->Plan(requests[s], kGiveUp); !r.ok()) {
      return r.status();
    }
  }
  for (int r = 0; r < repetitions; ++r) {
    for (int s = 0; s < 2; ++s) {
      const absl::Time start = absl::Now();
      absl::StatusOr<v1::PlanResult> result = servers[s]->Plan(requests[s], kGiveUp);
      plan_seconds[s].push_back(absl::ToDoubleSeconds(absl::Now() - start));
      if (!result.ok()) return result.status();
    }
  }
  for (int r = 0; r < 3; ++r) {
    for (int s = 0; s < 2; ++s) {
      absl::StatusOr<double> seconds = TimeBatch(*servers[s], requests[s], batch_jobs);
      if (!seconds.ok()) return seconds.status();
      batch_seconds[s].push_back(*seconds);
    }
  }
  out.sqlite_plan_seconds = Median(plan_seconds[0]).value_or(0);
  out.store_plan_seconds = Median(plan_seconds[1]).value_or(0);
  out.sqlite_batch_seconds = Median(batch_seconds[0]).value_or(0);
  out.store_batch_seconds = Median(batch_seconds[1]).value_or(0);
  return out;
}

}  // namespace swarmplan::bench
