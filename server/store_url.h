#pragma once

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "server/config.h"
#include "server/store.h"

namespace swarmplan::server {

// The store --store names: sqlite:DIR, or redis://HOST[:PORT][/DB] with the password (when
// any) read from --store-password-file. Without --store, SQLite in --data-dir.
absl::StatusOr<std::unique_ptr<Store>> OpenStore(const ServerConfig& config);

// What the log and the health answer say about the store, without secrets.
std::string DescribeStore(const ServerConfig& config);

}  // namespace swarmplan::server
