#pragma once

#include <string>

#include "absl/status/status.h"
#include "google/protobuf/duration.pb.h"
#include "google/protobuf/repeated_field.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::server {

// Bounds on what clients store with maps and jobs (documented in the .proto files). They keep
// every listing page far below the message limit.
inline constexpr int kMaxMapNameBytes = 256;
inline constexpr int kMaxLabels = 64;
inline constexpr int kMaxLabelKeyBytes = 63;
inline constexpr int kMaxLabelValueBytes = 256;
inline constexpr int kMaxClientRequestIdBytes = 128;

// INVALID_ARGUMENT naming `field` for a Duration outside google.protobuf.Duration's range
// (nanos beyond +-999,999,999, signs of seconds and nanos that differ) or below zero.
absl::Status CheckDuration(const std::string& field, const google::protobuf::Duration& duration);

// INVALID_ARGUMENT naming the field and the bound: labels, their keys and values,
// client_request_id.
absl::Status CheckRequestBounds(const v1::PlanRequest& request);

// INVALID_ARGUMENT for an empty name or one longer than kMaxMapNameBytes.
absl::Status CheckMapName(const std::string& name);

// INVALID_ARGUMENT naming states[i] for a value that is not a JobState a job can be in.
absl::Status CheckStateFilter(const google::protobuf::RepeatedField<int>& states);

}  // namespace swarmplan::server
