#pragma once

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "nlohmann/json.hpp"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::client {

// The job's final path (the timed path's points when the result has one, else the smoothed
// path, else the raw one) as a VDA 5050 order, version 3.0.0: one node per point (sequence ids
// 0, 2, 4, ..., nodePosition x, y in map units read as metres, theta the heading of the edge
// leaving it, mapId the job's map id) and one edge between each two (sequence ids 1, 3, ...,
// its length and, for a timed path, maximumSpeed: the top speed the timing reaches on it).
// orderId is the job id, orderUpdateId and headerId 0, timestamp `now`; manufacturer and
// serialNumber come from the job's labels of those names ("" without). FAILED_PRECONDITION
// without a path or for a path with heights (terrain).
absl::StatusOr<nlohmann::json> Vda5050Order(const v1::Job& job, absl::Time now);

}  // namespace swarmplan::client
