#include "tests/integration/redis_test_server.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/time/clock.h"
#include "server/redis_client.h"
#include "tests/integration/server_process.h"

namespace swarmplan::testing {

std::string RedisServerBinary() {
  const char* path = std::getenv("PATH");
  std::vector<std::string> dirs = absl::StrSplit(path != nullptr ? path : "", ':');
  dirs.push_back("/usr/bin");
  dirs.push_back("/usr/sbin");
  for (const std::string& dir : dirs) {
    if (dir.empty()) continue;
    const std::string candidate = dir + "/redis-server";
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

absl::StatusOr<std::unique_ptr<RedisTestServer>> RedisTestServer::Start(
    const std::string& dir, const std::string& password) {
  if (RedisServerBinary().empty()) {
    return absl::FailedPreconditionError(
        "redis-server is not installed (Debian package redis-server; scripts/install-deps)");
  }
  std::unique_ptr<RedisTestServer> server(new RedisTestServer(dir, password));
  absl::Status last;
  for (int attempt = 0; attempt < 5; ++attempt) {
    server->port_ = UnusedPort();
    last = server->Launch();
    if (last.ok()) return server;
  }
  return last;
}

RedisTestServer::~RedisTestServer() { Stop(); }

absl::Status RedisTestServer::Launch() {
  const std::string binary = RedisServerBinary();
  std::vector<std::string> args = {binary,
                                   "--port",
                                   absl::StrCat(port_),
                                   "--bind",
                                   "127.0.0.1",
                                   "--dir",
                                   dir_,
                                   "--appendonly",
                                   "yes",
                                   "--appendfsync",
                                   "always",
                                   "--save",
                                   "",
                                   "--daemonize",
                                   "no",
                                   "--logfile",
                                   dir_ + "/redis.log"};
  if (!password_.empty()) {
    args.push_back("--requirepass");
    args.push_back(password_);
  }
  // Built before fork: the child of a threaded process only calls async-signal-safe functions.
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_ = fork();
  if (pid_ < 0) return absl::InternalError("fork failed");
  if (pid_ == 0) {
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  server::RedisEndpoint endpoint{"127.0.0.1", port_, 0, password_};
  const absl::Time deadline = absl::Now() + absl::Seconds(20);
  while (absl::Now() < deadline) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return absl::UnavailableError(absl::StrCat("redis-server exited at start on port ", port_,
                                                 "; see ", dir_, "/redis.log"));
    }
    if (server::RedisClient::Connect(endpoint, 1, absl::Seconds(1)).ok()) {
      return absl::OkStatus();
    }
    absl::SleepFor(absl::Milliseconds(10));
  }
  Kill();
  return absl::DeadlineExceededError(
      absl::StrCat("redis-server on port ", port_, " did not answer within 20 s"));
}

void RedisTestServer::Stop() {
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  waitpid(pid_, nullptr, 0);
  pid_ = -1;
}

void RedisTestServer::Kill() {
  if (pid_ <= 0) return;
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  pid_ = -1;
}

absl::Status RedisTestServer::Restart() {
  if (pid_ > 0) return absl::FailedPreconditionError("redis-server is still running");
  return Launch();
}

}  // namespace swarmplan::testing
