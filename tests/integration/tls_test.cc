// TLS: with a certificate and key the server speaks only TLS. The certificate is made with
// the openssl command at test time; the test skips when it is not installed.
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tests/integration/test_server.h"

namespace swarmplan::testing {
namespace {

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(TlsTest, TlsClientsAreServedAndPlaintextClientsAreNot) {
  TempDir dir;
  const std::string cert = dir.path() + "/cert.pem";
  const std::string key = dir.path() + "/key.pem";
  const std::string command =
      "openssl req -x509 -newkey rsa:2048 -nodes -days 1 -subj /CN=localhost -keyout " + key +
      " -out " + cert + " >/dev/null 2>&1";
  if (std::system(command.c_str()) != 0) GTEST_SKIP() << "openssl is not available";

  TempDir data;
  server::ServerConfig config = TestServer::DefaultConfig();
  config.tls_cert_file = cert;
  config.tls_key_file = key;
  TestServer server(data.path(), config);
  const std::string target = "127.0.0.1:" + std::to_string(server.port());

  grpc::SslCredentialsOptions options;
  options.pem_root_certs = ReadAll(cert);
  grpc::ChannelArguments args;
  args.SetSslTargetNameOverride("localhost");
  auto tls = grpc::CreateCustomChannel(target, grpc::SslCredentials(options), args);
  v1::ListAlgorithmsResponse response;
  {
    grpc::ClientContext context;
    grpc::Status status =
        v1::AlgorithmService::NewStub(tls)->ListAlgorithms(&context, {}, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
  }
  {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(5));
    EXPECT_FALSE(server.algorithms().ListAlgorithms(&context, {}, &response).ok());
  }
}

}  // namespace
}  // namespace swarmplan::testing
