#pragma once

#include <string>

#include "client/connection.h"
#include "grpcpp/support/sync_stream.h"
#include "swarmplan/v1/jobs.grpc.pb.h"

// Following a job to its end, shared by `plan` and `jobs watch`: the live progress display,
// the summary table, the path written with --output, and the exit code.
namespace swarmplan::client {

struct FollowOptions {
  std::string action;           // "plan" or "jobs watch", for messages
  bool json_events = false;     // with --json: every event as one JSON line (else the final job)
  int expected_iterations = 0;  // for the ETA; 0 when unknown
  double time_budget_seconds = 0.0;
  std::string output_file;    // write the path here when set
  std::string output_format;  // "" = by extension
};

// Reads `reader` to the end, then fetches the job and prints it. Returns the exit code: 0 when
// the job succeeded, kExitNoPath for other final states, the RPC's code when the stream failed.
int FollowJobEvents(const GlobalOptions& global, const Connection& connection,
                    grpc::ClientReaderInterface<v1::JobEvent>& reader,
                    const FollowOptions& options);

// Prints a job for people: its request and state, then (when finished) the result table.
void PrintJob(const v1::Job& job);

// The iteration count the job runs at most: min of limits.max_iterations and the planner's
// parameter measured in "iterations" (as requested, else its default); 0 when unknown.
int ExpectedIterations(const Connection& connection, const v1::PlanRequest& request);

// Writes the job's path to options.output_file (when set); returns an exit code.
int WriteJobOutput(const GlobalOptions& global, const v1::Job& job, const std::string& file,
                   const std::string& format);

}  // namespace swarmplan::client
