#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "client/connection.h"
#include "grpcpp/support/status.h"
#include "swarmplan/v1/maps.pb.h"

namespace swarmplan::client {

// A map as the CLI's commands name it: a map version's id ("map-..."), or NAME@VERSION with
// VERSION a version number or "latest". Returns the GetMap request that reads it;
// INVALID_ARGUMENT naming `field` when the text after the last '@' is not a version.
absl::StatusOr<v1::GetMapRequest> ParseMapReference(const std::string& field,
                                                    const std::string& text);

// Sets *id to the id of the map version `reference` names: its id, or the id GetMap answers for
// its name and version. Returns GetMap's status (OK without a call for an id).
grpc::Status ResolveMapId(const Connection& connection, const v1::GetMapRequest& reference,
                          std::string* id);

}  // namespace swarmplan::client
