#include "client/exit_codes.h"

#include "absl/status/status.h"

namespace swarmplan::client {

int ExitCodeForStatus(grpc::StatusCode code) {
  switch (code) {
    case grpc::StatusCode::OK:
      return kExitOk;
    case grpc::StatusCode::UNAVAILABLE:
    case grpc::StatusCode::DEADLINE_EXCEEDED:
      return kExitUnavailable;
    case grpc::StatusCode::NOT_FOUND:
      return kExitNotFound;
    case grpc::StatusCode::INVALID_ARGUMENT:
    case grpc::StatusCode::FAILED_PRECONDITION:
    case grpc::StatusCode::OUT_OF_RANGE:
      return kExitInvalid;
    case grpc::StatusCode::RESOURCE_EXHAUSTED:
      return kExitResourceExhausted;
    case grpc::StatusCode::UNAUTHENTICATED:
    case grpc::StatusCode::PERMISSION_DENIED:
      return kExitUnauthenticated;
    default:
      return kExitOther;
  }
}

int ExitCodeForJobState(v1::JobState state) {
  return state == v1::JOB_STATE_SUCCEEDED ? kExitOk : kExitNoPath;
}

std::string StatusCodeName(grpc::StatusCode code) {
  // gRPC's codes are the canonical codes, which absl::StatusCode numbers identically.
  return absl::StatusCodeToString(static_cast<absl::StatusCode>(code));
}

std::string ExitCodesHelp() {
  return "Exit codes:\n"
         "  0   ok (plan, jobs watch: the job succeeded; health: the server is SERVING)\n"
         "  1   usage error: bad option or value, unreadable local file\n"
         "  2   server unreachable, not serving, or no answer within --timeout\n"
         "  3   not found: map, job or algorithm (an unknown --algorithm is NOT_FOUND)\n"
         "  4   invalid argument or failed precondition (bad field, start/goal blocked,\n"
         "      algorithm cannot plan on this kind of map)\n"
         "  5   the job finished without success: no path, cancelled, deadline exceeded, failed\n"
         "  6   resource exhausted: queue full, map too large, too many watchers\n"
         "  7   unauthenticated: missing or wrong --token-file\n"
         "  10  any other error\n"
         "\n"
         "With --json every command prints one JSON document on stdout (jobs watch: one JSON\n"
         "event per line); errors then print {\"error\": {...}} there too.";
}

}  // namespace swarmplan::client
