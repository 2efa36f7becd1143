// Measurement 2: many jobs at once on a server with a given number of workers (and
// measurement 5's batch over several replicas).
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "bench/service/bench_server.h"
#include "bench/service/measurements.h"

namespace swarmplan::bench {

absl::StatusOr<ThroughputResult> TimeJobs(const std::vector<BenchServer*>& servers,
                                          const v1::PlanRequest& request, int jobs) {
  const absl::Time start = absl::Now();
  std::vector<std::string> ids;
  for (int j = 0; j < jobs; ++j) {
    absl::StatusOr<v1::Job> job = servers[j % servers.size()]->Submit(request);
    if (!job.ok()) return job.status();
    ids.push_back(job->id());
  }
  ThroughputResult out;
  out.jobs = jobs;
  // Waiting for the jobs in submission order ends when the last one is final.
  absl::Time last_finished = start;
  for (size_t j = 0; j < ids.size(); ++j) {
    absl::StatusOr<v1::Job> job = servers[j % servers.size()]->WaitUntilFinal(
        ids[j], absl::Milliseconds(2), absl::Minutes(10));
    if (!job.ok()) return job.status();
    last_finished = absl::Now();
    if (job->state() == v1::JOB_STATE_SUCCEEDED || job->state() == v1::JOB_STATE_NO_PATH_FOUND) {
      ++out.succeeded;
    } else {
      return absl::InternalError(absl::StrCat("throughput job ", ids[j], " ended as ",
                                              v1::JobState_Name(job->state()), ": ",
                                              job->failure_reason()));
    }
  }
  out.seconds = absl::ToDoubleSeconds(last_finished - start);
  return out;
}

absl::StatusOr<ThroughputResult> MeasureThroughput(const PlanCase& plan, int workers, int jobs) {
  absl::StatusOr<std::unique_ptr<BenchServer>> server = BenchServer::Start(workers, jobs);
  if (!server.ok()) return server.status();
  absl::StatusOr<std::string> map_id = (*server)->UploadMapFile(plan.map_path);
  if (!map_id.ok()) return map_id.status();
  absl::StatusOr<ThroughputResult> out =
      TimeJobs({server->get()}, ToProtoRequest(plan, *map_id), jobs);
  if (out.ok()) out->workers = workers;
  return out;
}

}  // namespace swarmplan::bench
