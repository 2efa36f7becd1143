#pragma once

#include <sys/types.h>

#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "swarmplan/v1/jobs.grpc.pb.h"
#include "swarmplan/v1/maps.grpc.pb.h"

namespace swarmplan::testing {

// A port nobody listens on now (the kernel's pick for a socket bound to port 0).
int UnusedPort();

// The swarmplan-server binary in a child process on 127.0.0.1 (a free port), with stubs. Killed
// (SIGKILL) at destruction when still running.
class ServerProcess {
 public:
  // Starts the binary with `args` (besides --listen and --metrics-port=0) and waits until it
  // accepts connections.
  static absl::StatusOr<std::unique_ptr<ServerProcess>> Start(const std::vector<std::string>& args);
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  // SIGKILL and wait: what a crash of the machine leaves.
  void Kill();

  int port() const { return port_; }
  v1::MapService::Stub& maps() { return *maps_; }
  v1::JobService::Stub& jobs() { return *jobs_; }

 private:
  ServerProcess(pid_t pid, int port);

  pid_t pid_;
  int port_;
  std::unique_ptr<v1::MapService::Stub> maps_;
  std::unique_ptr<v1::JobService::Stub> jobs_;
};

}  // namespace swarmplan::testing
