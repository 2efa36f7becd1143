#pragma once

#include <string>

#include "absl/status/statusor.h"

namespace swarmplan::client {

// The gRPC target of --server: one HOST:PORT as it is, or a comma-separated list of replicas
// (HOST:PORT,HOST:PORT,...) as one ipv4: or ipv6: target over every address they resolve to,
// for round-robin balancing. INVALID_ARGUMENT naming --server for an entry without a port, and
// for names that do not resolve or resolve to both address families.
absl::StatusOr<std::string> ChannelTarget(const std::string& servers);

// Whether --server names several replicas.
bool IsServerList(const std::string& servers);

}  // namespace swarmplan::client
