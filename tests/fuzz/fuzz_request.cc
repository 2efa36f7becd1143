// Requests as the server receives them: an UploadMapRequest and a PlanRequest parsed by protobuf
// from the fuzzer's bytes (the first two bytes, little-endian, give the upload's length), then
// the server's map building (BuildMap, DescribeMap) and parameter conversion (FromProto), and
// the core's ValidatePlanRequest on the uploaded map. JobManager::Resolve, which joins these
// inside the server, is private to it: the few fields it copies are copied here the same way.

#include <algorithm>
#include <initializer_list>
#include <memory>

#include "core/registry.h"
#include "core/run.h"
#include "google/protobuf/stubs/logging.h"
#include "server/map_source.h"
#include "server/proto_convert.h"
#include "swarmplan/v1/jobs.pb.h"
#include "swarmplan/v1/maps.pb.h"
#include "tests/fuzz/fuzz_support.h"

namespace swarmplan::fuzz {
namespace {

void CheckCode(const absl::Status& status, std::initializer_list<absl::StatusCode> allowed) {
  if (status.ok()) return;
  for (absl::StatusCode code : allowed) {
    if (status.code() == code) return;
  }
  Fail("unexpected status code", status);
}

void Validate(const v1::PlanRequest& request, const MapPtr& map) {
  absl::StatusOr<ParamValues> params = server::FromProto(request.parameters());
  CheckCode(params.status(), {absl::StatusCode::kInvalidArgument});
  if (!params.ok() || map == nullptr) return;
  PlanRequest plan;
  plan.algorithm = request.algorithm();
  plan.params = std::move(*params);
  plan.smoothing = request.smoothing().empty() ? "none" : request.smoothing();
  plan.problem.map = map;
  plan.problem.start = server::FromProto(request.start());
  plan.problem.goal = server::FromProto(request.goal());
  plan.problem.clearance = request.clearance();
  plan.problem.limits.max_iterations = request.limits().max_iterations();
  plan.problem.limits.time_budget = server::FromProto(request.limits().time_budget());
  plan.problem.seed = request.seed() != 0 ? request.seed() : 1;
  CheckCode(ValidatePlanRequest(DefaultRegistry(), plan),
            {absl::StatusCode::kInvalidArgument, absl::StatusCode::kNotFound,
             absl::StatusCode::kFailedPrecondition});
}

}  // namespace
}  // namespace swarmplan::fuzz

// Protobuf logs every string field with invalid UTF-8 it parses; the parse result is what counts.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  google::protobuf::SetLogHandler(nullptr);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace swarmplan;
  if (size < 2) return 0;
  const size_t upload_size = std::min<size_t>(data[0] | (size_t{data[1]} << 8), size - 2);
  v1::UploadMapRequest upload;
  v1::PlanRequest request;
  if (!upload.ParseFromArray(data + 2, static_cast<int>(upload_size))) return 0;
  const bool plan_parsed =
      request.ParseFromArray(data + 2 + upload_size, static_cast<int>(size - 2 - upload_size));
  MapPtr map;
  absl::StatusOr<Map> built = server::BuildMap(upload.source(), fuzz::FuzzLoadOptions());
  fuzz::CheckCode(built.status(),
                  {absl::StatusCode::kInvalidArgument, absl::StatusCode::kResourceExhausted});
  if (built.ok()) {
    server::DescribeMap(*built);
    map = std::make_shared<const Map>(std::move(*built));
  }
  if (plan_parsed) fuzz::Validate(request, map);
  return 0;
}
