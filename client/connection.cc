#include "client/connection.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "client/server_list.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "grpcpp/support/channel_arguments.h"

namespace swarmplan::client {
namespace {

absl::StatusOr<std::string> ReadWholeFile(const std::string& path, const std::string& flag) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::FailedPreconditionError(absl::StrCat(flag, ": cannot read '", path, "'"));
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

}  // namespace

absl::StatusOr<Connection> Connection::Open(const GlobalOptions& options) {
  Connection connection;
  connection.timeout_seconds_ = options.timeout_seconds;
  if (!options.token_file.empty()) {
    absl::StatusOr<std::string> token = ReadWholeFile(options.token_file, "--token-file");
    if (!token.ok()) return token.status();
    std::string trimmed(absl::StripAsciiWhitespace(*token));
    if (trimmed.empty()) {
      return absl::FailedPreconditionError(
          absl::StrCat("--token-file: '", options.token_file, "' is empty"));
    }
    connection.authorization_ = absl::StrCat("Bearer ", trimmed);
  }
  std::shared_ptr<grpc::ChannelCredentials> credentials = grpc::InsecureChannelCredentials();
  if (!options.tls_ca.empty()) {
    absl::StatusOr<std::string> ca = ReadWholeFile(options.tls_ca, "--tls-ca");
    if (!ca.ok()) return ca.status();
    grpc::SslCredentialsOptions ssl;
    ssl.pem_root_certs = *ca;
    credentials = grpc::SslCredentials(ssl);
  }
  grpc::ChannelArguments arguments;
  arguments.SetMaxReceiveMessageSize(-1);  // maps and results can be large
  arguments.SetMaxSendMessageSize(-1);
  absl::StatusOr<std::string> target = ChannelTarget(options.server);
  if (!target.ok()) return target.status();
  if (IsServerList(options.server)) {
    // Each call goes to the next replica; TLS checks the certificate against the first name.
    arguments.SetLoadBalancingPolicyName("round_robin");
    arguments.SetString(GRPC_ARG_DEFAULT_AUTHORITY,
                        std::string(absl::StripAsciiWhitespace(
                            options.server.substr(0, options.server.find(',')))));
  }
  connection.channel_ = grpc::CreateCustomChannel(*target, credentials, arguments);
  return connection;
}

std::unique_ptr<grpc::ClientContext> Connection::UnaryContext() const {
  std::unique_ptr<grpc::ClientContext> context = StreamContext();
  context->set_deadline(std::chrono::system_clock::now() +
                        std::chrono::milliseconds(static_cast<int64_t>(timeout_seconds_ * 1000)));
  return context;
}

std::unique_ptr<grpc::ClientContext> Connection::StreamContext() const {
  auto context = std::make_unique<grpc::ClientContext>();
  if (!authorization_.empty()) context->AddMetadata("authorization", authorization_);
  return context;
}

}  // namespace swarmplan::client
