#include "absl/status/status.h"
#include "server/grpc_status.h"
#include "server/services.h"

namespace swarmplan::server {

absl::StatusOr<int> ResolvePageSize(int page_size) {
  if (page_size < 0) return absl::InvalidArgumentError("page_size: must be >= 0");
  if (page_size == 0) return 100;
  return std::min(page_size, 1000);
}

size_t PageByteBudget(const ServerConfig& config) {
  return static_cast<size_t>(
      std::min<int64_t>(config.max_page_bytes, config.max_message_bytes / 2));
}

grpc::ServerUnaryReactor* FinishUnary(grpc::CallbackServerContext* context,
                                      const grpc::Status& status) {
  grpc::ServerUnaryReactor* reactor = context->DefaultReactor();
  reactor->Finish(status);
  return reactor;
}

grpc::ServerUnaryReactor* MapServiceImpl::UploadMap(grpc::CallbackServerContext* context,
                                                    const v1::UploadMapRequest* request,
                                                    v1::UploadMapResponse* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::StatusOr<MapCatalog::UploadResult> result =
      maps_.Upload(request->name(), request->source());
  if (!result.ok()) return FinishUnary(context, ToGrpcStatus(result.status()));
  *response->mutable_map() = result->info;
  response->set_created(result->created);
  metrics_.SetMapsStored(maps_.size());
  return FinishUnary(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* MapServiceImpl::GetMap(grpc::CallbackServerContext* context,
                                                 const v1::GetMapRequest* request,
                                                 v1::GetMapResponse* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  if (!request->id().empty() && !request->name().empty()) {
    return FinishUnary(context, ToGrpcStatus(absl::InvalidArgumentError(
                                    "name: give the id or the name (with a version), not both")));
  }
  if (request->id().empty() && request->name().empty()) {
    return FinishUnary(context, ToGrpcStatus(absl::InvalidArgumentError(
                                    "id: required (or the map's name, with a version)")));
  }
  if (request->name().empty() && request->version() != 0) {
    return FinishUnary(context, ToGrpcStatus(absl::InvalidArgumentError(
                                    "version: needs the map's name (the id names one version)")));
  }
  absl::StatusOr<v1::MapInfo> info =
      request->name().empty() ? maps_.GetInfo(request->id())
                              : maps_.GetVersionInfo(request->name(), request->version());
  if (!info.ok()) return FinishUnary(context, ToGrpcStatus(info.status()));
  *response->mutable_map() = *std::move(info);
  if (request->include_source()) {
    absl::StatusOr<v1::MapSource> source = maps_.GetSource(response->map().id());
    if (!source.ok()) return FinishUnary(context, ToGrpcStatus(source.status()));
    *response->mutable_source() = std::move(*source);
  }
  return FinishUnary(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* MapServiceImpl::ListMaps(grpc::CallbackServerContext* context,
                                                   const v1::ListMapsRequest* request,
                                                   v1::ListMapsResponse* response) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::StatusOr<int> page_size = ResolvePageSize(request->page_size());
  if (!page_size.ok()) return FinishUnary(context, ToGrpcStatus(page_size.status()));
  absl::StatusOr<MapCatalog::Page> page =
      maps_.List(request->name(), *page_size, PageByteBudget(config_), request->page_token());
  if (!page.ok()) return FinishUnary(context, ToGrpcStatus(page.status()));
  for (v1::MapInfo& info : page->maps) *response->add_maps() = std::move(info);
  response->set_next_page_token(page->next_page_token);
  return FinishUnary(context, grpc::Status::OK);
}

grpc::ServerUnaryReactor* MapServiceImpl::DeleteMap(grpc::CallbackServerContext* context,
                                                    const v1::DeleteMapRequest* request,
                                                    v1::DeleteMapResponse*) {
  if (grpc::Status s = auth_.Check(*context); !s.ok()) return FinishUnary(context, s);
  absl::Status status = jobs_.DeleteMap(request->id());
  metrics_.SetMapsStored(maps_.size());
  return FinishUnary(context, ToGrpcStatus(status));
}

}  // namespace swarmplan::server
