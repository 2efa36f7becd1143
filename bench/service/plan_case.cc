#include "bench/service/plan_case.h"

#include <memory>

#include "absl/strings/str_cat.h"
#include "core/map/io/map_io.h"
#include "server/proto_convert.h"

namespace swarmplan::bench {

absl::StatusOr<PlanRequest> ToCoreRequest(const PlanCase& plan) {
  absl::StatusOr<Map> map = LoadMapFile(plan.map_path);
  if (!map.ok()) return map.status();
  PlanRequest request;
  request.algorithm = plan.algorithm;
  request.params = plan.params;
  request.problem.map = std::make_shared<const Map>(std::move(*map));
  request.problem.start = plan.start;
  request.problem.goal = plan.goal;
  request.problem.seed = plan.seed;
  return request;
}

v1::PlanRequest ToProtoRequest(const PlanCase& plan, const std::string& map_id,
                               int progress_every) {
  v1::PlanRequest request;
  request.set_map_id(map_id);
  request.set_algorithm(plan.algorithm);
  for (const auto& [name, value] : plan.params) {
    (*request.mutable_parameters())[name] = server::ToProto(value);
  }
  *request.mutable_start() = server::ToProto(plan.start);
  *request.mutable_goal() = server::ToProto(plan.goal);
  request.set_seed(plan.seed);
  request.mutable_progress()->set_every_iterations(progress_every);
  return request;
}

std::string DescribeDifference(const PlanResult& in_process, const v1::PlanResult& served) {
  if (in_process.found != served.found()) return "found differs";
  if (in_process.seed != served.seed()) return "seed differs";
  if (in_process.iterations != served.iterations()) return "iterations differ";
  if (in_process.evaluations != served.evaluations()) return "evaluations differ";
  if (in_process.fitness != served.fitness()) return "fitness differs";
  if (static_cast<int>(in_process.raw_path.size()) != served.raw_path_size()) {
    return "path sizes differ";
  }
  for (int i = 0; i < served.raw_path_size(); ++i) {
    if (server::FromProto(served.raw_path(i)) != in_process.raw_path[i]) {
      return absl::StrCat("path point ", i, " differs");
    }
  }
  return "";
}

}  // namespace swarmplan::bench
