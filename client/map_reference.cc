#include "client/map_reference.h"

#include "absl/status/status.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "swarmplan/v1/maps.grpc.pb.h"

namespace swarmplan::client {

absl::StatusOr<v1::GetMapRequest> ParseMapReference(const std::string& field,
                                                    const std::string& text) {
  v1::GetMapRequest request;
  const size_t at = text.rfind('@');
  if (at == std::string::npos) {
    request.set_id(text);
    return request;
  }
  if (at == 0) {
    return absl::InvalidArgumentError(
        absl::StrCat(field, ": '", text, "' has no map name before '@' (NAME@VERSION)"));
  }
  const std::string version = text.substr(at + 1);
  int64_t number = 0;
  if (version != "latest" && (!absl::SimpleAtoi(version, &number) || number < 1)) {
    return absl::InvalidArgumentError(absl::StrCat(
        field, ": '", version, "' is not a version (a number from 1, or 'latest'; NAME@VERSION)"));
  }
  request.set_name(text.substr(0, at));
  request.set_version(number);
  return request;
}

grpc::Status ResolveMapId(const Connection& connection, const v1::GetMapRequest& reference,
                          std::string* id) {
  if (reference.name().empty()) {
    *id = reference.id();
    return grpc::Status::OK;
  }
  auto stub = v1::MapService::NewStub(connection.channel());
  v1::GetMapResponse response;
  const grpc::Status status = stub->GetMap(connection.UnaryContext().get(), reference, &response);
  if (status.ok()) *id = response.map().id();
  return status;
}

}  // namespace swarmplan::client
