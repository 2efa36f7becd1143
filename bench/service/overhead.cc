// Measurement 1: the same plan in-process and through the server.
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "bench/service/bench_server.h"
#include "bench/service/measurements.h"
#include "bench/statistics.h"
#include "core/registry.h"

namespace swarmplan::bench {
namespace {

constexpr absl::Duration kJobGiveUp = absl::Minutes(5);

absl::StatusOr<PlanResult> RunInProcess(const PlanRequest& request) {
  StopToken stop;
  NullObserver observer;
  return RunPlan(DefaultRegistry(), request, stop, observer);
}

absl::StatusOr<v1::PlanResult> RunSubmitGet(BenchServer& server, const v1::PlanRequest& request) {
  absl::StatusOr<v1::Job> job = server.Submit(request);
  if (!job.ok()) return job.status();
  job = server.WaitUntilFinal(job->id(), absl::Milliseconds(1), kJobGiveUp);
  if (!job.ok()) return job.status();
  return job->result();
}

// Runs `run`, adds its wall time to `seconds`, and checks its result against `reference`.
template <typename Run>
absl::Status TimeServed(Run run, const PlanResult& reference, const std::string& path_name,
                        std::vector<double>& seconds, OverheadResult& out) {
  const absl::Time start = absl::Now();
  absl::StatusOr<v1::PlanResult> served = run();
  seconds.push_back(absl::ToDoubleSeconds(absl::Now() - start));
  if (!served.ok()) return served.status();
  if (std::string difference = DescribeDifference(reference, *served);
      !difference.empty() && out.difference.empty()) {
    out.difference = absl::StrCat(path_name, ": ", difference);
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<OverheadResult> MeasureOverhead(const PlanCase& plan, int repetitions) {
  absl::StatusOr<PlanRequest> core_request = ToCoreRequest(plan);
  if (!core_request.ok()) return core_request.status();
  absl::StatusOr<std::unique_ptr<BenchServer>> server = BenchServer::Start(1, 4);
  if (!server.ok()) return server.status();
  absl::StatusOr<std::string> map_id = (*server)->UploadMapFile(plan.map_path);
  if (!map_id.ok()) return map_id.status();
  const v1::PlanRequest request = ToProtoRequest(plan, *map_id);

  OverheadResult out;
  out.label = absl::StrCat(plan.algorithm, " on ",
                           std::filesystem::path(plan.map_path).filename().string());
  out.repetitions = repetitions;
  absl::StatusOr<PlanResult> reference = RunInProcess(*core_request);
  if (!reference.ok()) return reference.status();

  std::vector<double> in_process, stream, submit_get, warm_up;
  auto plan_stream = [&] { return (*server)->Plan(request, kJobGiveUp); };
  auto submit_then_get = [&] { return RunSubmitGet(**server, request); };
  // One untimed call of each path first: connection set-up and first-use costs.
  if (absl::Status s = TimeServed(plan_stream, *reference, "Plan", warm_up, out); !s.ok()) {
    return s;
  }
  if (absl::Status s = TimeServed(submit_then_get, *reference, "SubmitPlan+GetJob", warm_up, out);
      !s.ok()) {
    return s;
  }
  for (int r = 0; r < repetitions; ++r) {
    const absl::Time start = absl::Now();
    absl::StatusOr<PlanResult> result = RunInProcess(*core_request);
    in_process.push_back(absl::ToDoubleSeconds(absl::Now() - start));
    if (!result.ok()) return result.status();
    if (result->raw_path != reference->raw_path && out.difference.empty()) {
      out.difference = "in-process runs differ from each other";
    }
    if (absl::Status s = TimeServed(plan_stream, *reference, "Plan", stream, out); !s.ok()) {
      return s;
    }
    if (absl::Status s =
            TimeServed(submit_then_get, *reference, "SubmitPlan+GetJob", submit_get, out);
        !s.ok()) {
      return s;
    }
  }
  out.identical = out.difference.empty();
  out.in_process_seconds = Median(in_process).value_or(0);
  out.plan_stream_seconds = Median(stream).value_or(0);
  out.submit_get_seconds = Median(submit_get).value_or(0);
  return out;
}

}  // namespace swarmplan::bench
