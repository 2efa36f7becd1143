#pragma once

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "grpcpp/channel.h"
#include "grpcpp/client_context.h"

namespace swarmplan::client {

// The options every command takes (before or after the subcommand).
struct GlobalOptions {
  std::string server = "127.0.0.1:50051";  // host:port; env SWARMPLAN_SERVER
  double timeout_seconds = 30.0;           // per unary call, and for connecting
  bool json = false;                       // machine-readable output on stdout
  std::string token_file;                  // bearer token sent with every call
  std::string tls_ca;                      // PEM root certificates: use TLS
};

// A channel to the server with the authentication and deadlines the options ask for.
class Connection {
 public:
  // FAILED_PRECONDITION naming the flag when the token or CA file cannot be read.
  static absl::StatusOr<Connection> Open(const GlobalOptions& options);

  const std::shared_ptr<grpc::Channel>& channel() const { return channel_; }

  // A context for a unary call: deadline now + --timeout, and the token.
  std::unique_ptr<grpc::ClientContext> UnaryContext() const;
  // A context for a stream that lasts as long as the job: no deadline, only the token.
  std::unique_ptr<grpc::ClientContext> StreamContext() const;

 private:
  std::shared_ptr<grpc::Channel> channel_;
  std::string authorization_;  // "Bearer <token>" or empty
  double timeout_seconds_ = 30.0;
};

}  // namespace swarmplan::client
