#pragma once

#include <memory>

#include "absl/status/statusor.h"
#include "core/registry.h"
#include "server/config.h"

namespace swarmplan::server {

// The whole service in one object: store, maps, jobs, metrics, gRPC server. Tests start it
// in-process on 127.0.0.1:0 with their own Registry.
class Server {
 public:
  // Opens the store, loads maps and jobs, starts the workers, metrics and the gRPC listener.
  // `registry` must outlive the server.
  static absl::StatusOr<std::unique_ptr<Server>> Start(const ServerConfig& config,
                                                       const Registry& registry);
  ~Server();  // Shutdown()

  // The gRPC port (the one picked when the config said 0).
  int port() const;
  // The /metrics port, 0 when metrics are off.
  int metrics_port() const;

  // Graceful: stops accepting jobs and calls, gives running jobs the grace period to finish,
  // re-queues the others in the store, then closes. Idempotent; thread-safe.
  void Shutdown();
  // Blocks until Shutdown() has completed.
  void Wait();

 private:
  struct Impl;
  explicit Server(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace swarmplan::server
