// swarmplan health: the standard gRPC health check (grpc.health.v1.Health/Check).
//
// The two messages are tiny, so they are encoded here by hand instead of linking generated
// code for grpc/health/v1/health.proto:
//   HealthCheckRequest  { string service = 1; }
//   HealthCheckResponse { ServingStatus status = 1; }  UNKNOWN 0, SERVING 1, NOT_SERVING 2,
//                                                      SERVICE_UNKNOWN 3
#include <iostream>
#include <memory>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "client/exit_codes.h"
#include "client/output.h"
#include "grpcpp/impl/client_unary_call.h"
#include "grpcpp/impl/rpc_method.h"
#include "grpcpp/support/byte_buffer.h"
#include "nlohmann/json.hpp"

namespace swarmplan::client {
namespace {

constexpr char kCheckMethod[] = "/grpc.health.v1.Health/Check";

grpc::ByteBuffer EncodeRequest(const std::string& service) {
  std::string bytes;
  if (!service.empty()) {
    bytes.push_back(0x0A);  // field 1, length-delimited
    size_t length = service.size();
    do {
      uint8_t byte = length & 0x7F;
      length >>= 7;
      if (length != 0) byte |= 0x80;
      bytes.push_back(static_cast<char>(byte));
    } while (length != 0);
    bytes += service;
  }
  grpc::Slice slice(bytes);
  return grpc::ByteBuffer(&slice, 1);
}

// The status field of a HealthCheckResponse; 0 (UNKNOWN) when absent or unreadable.
int DecodeStatus(const grpc::ByteBuffer& buffer) {
  grpc::Slice slice;
  if (!buffer.DumpToSingleSlice(&slice).ok()) return 0;
  const uint8_t* data = slice.begin();
  const size_t size = slice.size();
  size_t i = 0;
  auto read_varint = [&](uint64_t* value) {
    *value = 0;
    for (int shift = 0; i < size && shift < 64; shift += 7) {
      const uint8_t byte = data[i++];
      *value |= uint64_t(byte & 0x7F) << shift;
      if ((byte & 0x80) == 0) return true;
    }
    return false;
  };
  int status = 0;
  while (i < size) {
    uint64_t key = 0;
    if (!read_varint(&key)) return 0;
    const int field = static_cast<int>(key >> 3);
    const int wire_type = static_cast<int>(key & 7);
    uint64_t value = 0;
    if (wire_type == 0) {
      if (!read_varint(&value)) return 0;
      if (field == 1) status = static_cast<int>(value);
    } else if (wire_type == 2) {
      if (!read_varint(&value) || value > size - i) return 0;
      i += value;
    } else {
      return 0;  // not a HealthCheckResponse
    }
  }
  return status;
}

const char* ServingStatusName(int status) {
  switch (status) {
    case 1:
      return "SERVING";
    case 2:
      return "NOT_SERVING";
    case 3:
      return "SERVICE_UNKNOWN";
    default:
      return "UNKNOWN";
  }
}

int Run(const GlobalOptions& global, const std::string& service) {
  absl::StatusOr<Connection> connection = Connection::Open(global);
  if (!connection.ok()) return ReportLocalError(global, connection.status());
  const grpc::internal::RpcMethod method(kCheckMethod, grpc::internal::RpcMethod::NORMAL_RPC);
  std::unique_ptr<grpc::ClientContext> context = connection->UnaryContext();
  grpc::ByteBuffer response;
  grpc::Status status = grpc::internal::BlockingUnaryCall<grpc::ByteBuffer, grpc::ByteBuffer>(
      connection->channel().get(), method, context.get(), EncodeRequest(service), &response);
  if (!status.ok()) return ReportRpcError(global, "health", status);
  const int serving = DecodeStatus(response);
  const int exit_code = serving == 1 ? kExitOk : kExitUnavailable;
  if (global.json) {
    nlohmann::json result = {{"server", global.server},
                             {"service", service},
                             {"status", ServingStatusName(serving)},
                             {"exit_code", exit_code}};
    std::cout << result.dump(2) << "\n";
  } else {
    std::cout << global.server << (service.empty() ? "" : absl::StrCat(" ", service)) << ": "
              << ServingStatusName(serving) << "\n";
  }
  return exit_code;
}

}  // namespace

void AddHealthCommand(CLI::App& app, const GlobalOptions& global, Action* action) {
  auto service = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "health", "Ask the server's gRPC health service; exit 0 when SERVING, 2 otherwise");
  command->add_option("--service", *service,
                      "A service name, e.g. swarmplan.v1.JobService (default: the server)");
  OnChosen(command, action, [&global, service] { return Run(global, *service); });
}

}  // namespace swarmplan::client
