#include "server/job.h"

#include "absl/strings/ascii.h"
#include "server/proto_convert.h"

namespace swarmplan::server {

bool IsFinal(v1::JobState state) {
  return state != v1::JOB_STATE_UNSPECIFIED && state != v1::JOB_STATE_QUEUED &&
         state != v1::JOB_STATE_RUNNING;
}

v1::JobEvent FinishedEvent(const v1::Job& record) {
  v1::JobEvent finished;
  finished.mutable_finished()->set_state(record.state());
  if (record.has_result()) *finished.mutable_finished()->mutable_result() = record.result();
  finished.mutable_finished()->set_failure_reason(record.failure_reason());
  return finished;
}

StoredJob ToStored(const std::string& id, const v1::Job& record) {
  StoredJob stored;
  stored.id = id;
  stored.state = record.state();
  record.SerializeToString(&stored.record);
  stored.created_at = FromProto(record.created_at());
  stored.client_request_id = record.request().client_request_id();
  if (IsFinal(record.state())) stored.finished_at = FromProto(record.finished_at());
  return stored;
}

std::string StateLabel(v1::JobState state) {
  std::string name = v1::JobState_Name(state);
  constexpr std::string_view kPrefix = "JOB_STATE_";
  if (name.rfind(kPrefix, 0) == 0) name = name.substr(kPrefix.size());
  return absl::AsciiStrToLower(name);
}

}  // namespace swarmplan::server
