// Measurement 2: many jobs at once on a server with a given number of workers.
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "bench/service/bench_server.h"
#include "bench/service/measurements.h"

namespace swarmplan::bench {

absl::StatusOr<ThroughputResult> MeasureThroughput(const PlanCase& plan, int workers, int jobs) {
  absl::StatusOr<std::unique_ptr<BenchServer>> server = BenchServer::Start(workers, jobs);
  if (!server.ok()) return server.status();
  absl::StatusOr<std::string> map_id = (*server)->UploadMapFile(plan.map_path);
  if (!map_id.ok()) return map_id.status();
  const v1::PlanRequest request = ToProtoRequest(plan, *map_id);

  const absl::Time start = absl::Now();
  std::vector<std::string> ids;
  for (int j = 0; j < jobs; ++j) {
    absl::StatusOr<v1::Job> job = (*server)->Submit(request);
    if (!job.ok()) return job.status();
    ids.push_back(job->id());
  }
  ThroughputResult out;
  out.workers = workers;
  out.jobs = jobs;
  // Waiting for the jobs in submission order ends when the last one is final.
  absl::Time last_finished = start;
  for (const std::string& id : ids) {
    absl::StatusOr<v1::Job> job =
        (*server)->WaitUntilFinal(id, absl::Milliseconds(2), absl::Minutes(10));
    if (!job.ok()) return job.status();
    last_finished = absl::Now();
    if (job->state() == v1::JOB_STATE_SUCCEEDED || job->state() == v1::JOB_STATE_NO_PATH_FOUND) {
      ++out.succeeded;
    } else {
      return absl::InternalError(absl::StrCat("throughput job ", id, " ended as ",
                                              v1::JobState_Name(job->state()), ": ",
                                              job->failure_reason()));
    }
  }
  out.seconds = absl::ToDoubleSeconds(last_finished - start);
  return out;
}

}  // namespace swarmplan::bench
