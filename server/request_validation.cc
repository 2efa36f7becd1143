#include "server/request_validation.h"

#include "absl/strings/str_cat.h"

namespace swarmplan::server {
namespace {

constexpr int64_t kMaxDurationSeconds = 315576000000;  // google.protobuf.Duration's range
constexpr int32_t kMaxNanos = 999999999;

}  // namespace

absl::Status CheckDuration(const std::string& field, const google::protobuf::Duration& duration) {
  const int64_t seconds = duration.seconds();
  const int32_t nanos = duration.nanos();
  if (nanos < -kMaxNanos || nanos > kMaxNanos) {
    return absl::InvalidArgumentError(
        absl::StrCat(field, ": nanos ", nanos, " is outside [-999999999, 999999999]"));
  }
  if (seconds < -kMaxDurationSeconds || seconds > kMaxDurationSeconds) {
    return absl::InvalidArgumentError(
        absl::StrCat(field, ": seconds ", seconds, " is outside [-315576000000, 315576000000]"));
  }
  if ((seconds > 0 && nanos < 0) || (seconds < 0 && nanos > 0)) {
    return absl::InvalidArgumentError(
        absl::StrCat(field, ": seconds and nanos must have the same sign"));
  }
  if (seconds < 0 || nanos < 0) {
    return absl::InvalidArgumentError(absl::StrCat(field, ": must not be negative"));
  }
  return absl::OkStatus();
}

absl::Status CheckRequestBounds(const v1::PlanRequest& request) {
  if (request.labels_size() > kMaxLabels) {
    return absl::InvalidArgumentError(absl::StrCat("labels: ", request.labels_size(),
                                                   " labels; at most ", kMaxLabels, " allowed"));
  }
  for (const auto& [key, value] : request.labels()) {
    if (key.empty() || key.size() > static_cast<size_t>(kMaxLabelKeyBytes)) {
      return absl::InvalidArgumentError(absl::StrCat("labels: a key of ", key.size(),
                                                     " bytes; keys must have 1 to ",
                                                     kMaxLabelKeyBytes, " bytes"));
    }
    if (value.size() > static_cast<size_t>(kMaxLabelValueBytes)) {
      return absl::InvalidArgumentError(absl::StrCat("labels['", key, "']: ", value.size(),
                                                     " bytes; at most ", kMaxLabelValueBytes,
                                                     " allowed"));
    }
  }
  if (request.client_request_id().size() > static_cast<size_t>(kMaxClientRequestIdBytes)) {
    return absl::InvalidArgumentError(
        absl::StrCat("client_request_id: ", request.client_request_id().size(), " bytes; at most ",
                     kMaxClientRequestIdBytes, " allowed"));
  }
  return absl::OkStatus();
}

absl::Status CheckMapName(const std::string& name) {
  if (name.empty()) return absl::InvalidArgumentError("name: required");
  if (name.size() > static_cast<size_t>(kMaxMapNameBytes)) {
    return absl::InvalidArgumentError(
        absl::StrCat("name: ", name.size(), " bytes; at most ", kMaxMapNameBytes, " allowed"));
  }
  return absl::OkStatus();
}

absl::Status CheckStateFilter(const google::protobuf::RepeatedField<int>& states) {
  for (int i = 0; i < states.size(); ++i) {
    const int state = states.Get(i);
    if (!v1::JobState_IsValid(state) || state == v1::JOB_STATE_UNSPECIFIED) {
      return absl::InvalidArgumentError(
          absl::StrCat("states[", i, "]: ", state, " is not a job state (JOB_STATE_QUEUED = 1 ... ",
                       "JOB_STATE_FAILED = 7)"));
    }
  }
  return absl::OkStatus();
}

}  // namespace swarmplan::server
