// Measurement 5: replicas on one shared store. The same batch of jobs, submitted round-robin
// to 1, 2, ... replicas of 1 worker each that share one Redis queue.
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "bench/service/bench_server.h"
#include "bench/service/measurements.h"

namespace swarmplan::bench {

absl::StatusOr<ReplicasResult> MeasureReplicas(const PlanCase& plan, const std::string& store,
                                               int replicas, int jobs) {
  std::vector<std::unique_ptr<BenchServer>> servers;
  for (int r = 0; r < replicas; ++r) {
    absl::StatusOr<std::unique_ptr<BenchServer>> server = BenchServer::Start(1, jobs, store);
    if (!server.ok()) return server.status();
    servers.push_back(std::move(*server));
  }
  // Uploaded once, through the first replica; the others read it from the store.
  absl::StatusOr<std::string> map_id = servers.front()->UploadMapFile(plan.map_path);
  if (!map_id.ok()) return map_id.status();
  const v1::PlanRequest request = ToProtoRequest(plan, *map_id);
  // Every replica parses the map once before the clock starts, as it would in service.
  for (auto& server : servers) {
    if (absl::StatusOr<v1::PlanResult> warm = server->Plan(request, absl::Minutes(5)); !warm.ok()) {
      return warm.status();
    }
  }

  const absl::Time start = absl::Now();
  std::vector<std::string> ids;
  for (int j = 0; j < jobs; ++j) {
    absl::StatusOr<v1::Job> job = servers[j % replicas]->Submit(request);
    if (!job.ok()) return job.status();
    ids.push_back(job->id());
  }
  ReplicasResult out;
  out.replicas = replicas;
  out.jobs = jobs;
  absl::Time last_finished = start;
  for (size_t j = 0; j < ids.size(); ++j) {
    absl::StatusOr<v1::Job> job =
        servers[j % replicas]->WaitUntilFinal(ids[j], absl::Milliseconds(2), absl::Minutes(10));
    if (!job.ok()) return job.status();
    last_finished = absl::Now();
    if (job->state() != v1::JOB_STATE_SUCCEEDED) {
      return absl::InternalError(absl::StrCat("replicas job ", ids[j], " ended as ",
                                              v1::JobState_Name(job->state()), ": ",
                                              job->failure_reason()));
    }
    ++out.succeeded;
  }
  out.seconds = absl::ToDoubleSeconds(last_finished - start);
  return out;
}

}  // namespace swarmplan::bench
