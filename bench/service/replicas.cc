// Measurement 5: replicas on one shared store. The same batch of jobs, submitted round-robin
// to 1, 2, ... replicas of 1 worker each that share one Redis queue.
#include "bench/service/bench_server.h"
#include "bench/service/measurements.h"

namespace swarmplan::bench {

absl::StatusOr<ThroughputResult> MeasureReplicas(const PlanCase& plan, const std::string& store,
                                                 int replicas, int jobs) {
  std::vector<std::unique_ptr<BenchServer>> servers;
  std::vector<BenchServer*> targets;
  for (int r = 0; r < replicas; ++r) {
    absl::StatusOr<std::unique_ptr<BenchServer>> server = BenchServer::Start(1, jobs, store);
    if (!server.ok()) return server.status();
    targets.push_back(server->get());
    servers.push_back(std::move(*server));
  }
  // Uploaded once, through the first replica; the others read it from the store.
  absl::StatusOr<std::string> map_id = servers.front()->UploadMapFile(plan.map_path);
  if (!map_id.ok()) return map_id.status();
  const v1::PlanRequest request = ToProtoRequest(plan, *map_id);
  // Every replica parses the map once before the clock starts, as it would in service.
  for (BenchServer* server : targets) {
    if (absl::StatusOr<v1::PlanResult> warm = server->Plan(request, absl::Minutes(5)); !warm.ok()) {
      return warm.status();
    }
  }
  absl::StatusOr<ThroughputResult> out = TimeJobs(targets, request, jobs);
  if (out.ok()) out->workers = replicas;
  return out;
}

}  // namespace swarmplan::bench
