#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "core/run.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::bench {

// One plan, stated once and sent both ways: to core RunPlan and to the server.
struct PlanCase {
  std::string map_path;
  std::string algorithm;
  ParamValues params;
  Point3 start = Point3::Zero();
  Point3 goal = Point3::Zero();
  uint64_t seed = 1;
};

// The in-process request, with the map read from `map_path` as the server reads an upload.
absl::StatusOr<PlanRequest> ToCoreRequest(const PlanCase& plan);
// The gRPC request for the map uploaded as `map_id`; progress every `progress_every` iterations.
v1::PlanRequest ToProtoRequest(const PlanCase& plan, const std::string& map_id,
                               int progress_every = 0);

// "" when both results hold the same path, fitness, iterations, evaluations and seed; otherwise
// what differs first.
std::string DescribeDifference(const PlanResult& in_process, const v1::PlanResult& served);

}  // namespace swarmplan::bench
