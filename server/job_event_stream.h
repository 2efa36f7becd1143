#pragma once

#include <grpcpp/support/server_callback.h>

#include "server/job_manager.h"

namespace swarmplan::server {

// Streams a job's events to one client (Plan and WatchJob). At most one write in flight; the
// next write starts from OnWriteDone or when the job publishes; never blocks; always Finishes:
// OK after the finished event, CANCELLED when the client went away.
//
// `cursor`: the sequence after which to start (0: from the first event). `owner`: this is the
// Plan call that submitted the job, whose departure may cancel it.
grpc::ServerWriteReactor<v1::JobEvent>* StreamJobEvents(JobManager& manager, JobPtr job,
                                                        int64_t cursor, bool owner,
                                                        int max_watchers);

// A stream that ends at once with `status`.
grpc::ServerWriteReactor<v1::JobEvent>* FailedJobEventStream(const grpc::Status& status);

}  // namespace swarmplan::server
