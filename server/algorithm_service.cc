#include "server/grpc_status.h"
#include "server/proto_convert.h"
#include "server/services.h"

namespace swarmplan::server {

grpc::ServerUnaryReactor* AlgorithmServiceImpl::ListAlgorithms(
    grpc::CallbackServerContext* context, const v1::ListAlgorithmsRequest*,
    v1::ListAlgorithmsResponse* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  for (const PlannerInfo& info : registry_.planners()) *response->add_algorithms() = ToProto(info);
  return FinishUnary(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* AlgorithmServiceImpl::GetAlgorithm(grpc::CallbackServerContext* context,
                                                             const v1::GetAlgorithmRequest* request,
                                                             v1::Algorithm* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::StatusOr<const PlannerInfo*> info = registry_.Get(request->id());
  if (!info.ok()) return FinishUnary(context, ToGrpcStatus(info.status()));
  *response = ToProto(**info);
  return FinishUnary(context, grpc::Status::OK);
}

}  // namespace swarmplan::server
