#pragma once

#include <sys/types.h>

#include <memory>
#include <string>

#include "absl/status/statusor.h"

namespace swarmplan::testing {

// The redis-server binary on PATH (or /usr/bin), "" when it is not installed.
std::string RedisServerBinary();

// A real redis-server on a free 127.0.0.1 port, its AOF (appendfsync always) in a directory the
// caller owns. Stopped (SIGTERM, AOF flushed) at destruction.
class RedisTestServer {
 public:
  // FAILED_PRECONDITION when redis-server is not installed.
  static absl::StatusOr<std::unique_ptr<RedisTestServer>> Start(const std::string& dir,
                                                                const std::string& password = "");
  ~RedisTestServer();
  RedisTestServer(const RedisTestServer&) = delete;
  RedisTestServer& operator=(const RedisTestServer&) = delete;

  int port() const { return port_; }
  std::string url() const { return "redis://127.0.0.1:" + std::to_string(port_); }

  // SIGTERM and wait: Redis writes its AOF and exits.
  void Stop();
  // SIGKILL and wait: what a crash leaves.
  void Kill();
  // Starts again on the same port and directory (after Stop or Kill); Redis reloads its AOF.
  absl::Status Restart();

 private:
  RedisTestServer(std::string dir, std::string password)
      : dir_(std::move(dir)), password_(std::move(password)) {}
  // Starts redis-server on port_ and waits until it answers PING.
  absl::Status Launch();

  const std::string dir_;
  const std::string password_;
  int port_ = 0;
  pid_t pid_ = -1;
};

}  // namespace swarmplan::testing
