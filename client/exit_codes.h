#pragma once

#include <string>

#include "grpcpp/support/status.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::client {

// The exit codes scripts can rely on. Listed in `swarmplan --help` by ExitCodesHelp().
enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 1,              // bad command line, unreadable local file
  kExitUnavailable = 2,        // server unreachable, not serving, or did not answer in time
  kExitNotFound = 3,           // map, job or algorithm not found
  kExitInvalid = 4,            // invalid argument or failed precondition
  kExitNoPath = 5,             // the job finished without success
  kExitResourceExhausted = 6,  // queue full, map too large, too many watchers
  kExitUnauthenticated = 7,    // missing or wrong token
  kExitOther = 10,             // anything else
};

// The exit code for a failed RPC.
int ExitCodeForStatus(grpc::StatusCode code);
// 0 for a succeeded job, kExitNoPath for every other final state.
int ExitCodeForJobState(v1::JobState state);
// "NOT_FOUND", "UNAVAILABLE", ...
std::string StatusCodeName(grpc::StatusCode code);
// The footer of `swarmplan --help`.
std::string ExitCodesHelp();

}  // namespace swarmplan::client
