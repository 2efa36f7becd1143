#include "client/output.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "absl/time/time.h"
#include "client/exit_codes.h"
#include "google/protobuf/util/json_util.h"
#include "nlohmann/json.hpp"

namespace swarmplan::client {

void Table::Print(std::ostream& out) const {
  std::vector<size_t> widths(headers_.size(), 0);
  auto widen = [&](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size() && i < widths.size(); ++i) {
      widths[i] = std::max(widths[i], cells[i].size());
    }
  };
  widen(headers_);
  for (const auto& row : rows_) widen(row);
  auto print_row = [&](const std::vector<std::string>& cells) {
    std::string line;
    for (size_t i = 0; i < widths.size(); ++i) {
      const std::string cell = i < cells.size() ? cells[i] : "";
      line += cell;
      if (i + 1 < widths.size()) line += std::string(widths[i] - cell.size() + 2, ' ');
    }
    out << std::string(absl::StripTrailingAsciiWhitespace(line)) << "\n";
  };
  print_row(headers_);
  for (const auto& row : rows_) print_row(row);
}

void PrintKeyValues(std::ostream& out, const KeyValues& rows) {
  size_t width = 0;
  for (const auto& [key, value] : rows) width = std::max(width, key.size());
  for (const auto& [key, value] : rows) {
    out << key << ":" << std::string(width - key.size() + 2, ' ') << value << "\n";
  }
}

std::string ProtoToJson(const google::protobuf::Message& message, bool pretty) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = pretty;
  options.always_print_primitive_fields = true;
  options.preserve_proto_field_names = true;
  std::string json;
  if (!google::protobuf::util::MessageToJsonString(message, &json, options).ok()) return "{}";
  return json;
}

void PrintJson(const google::protobuf::Message& message) { std::cout << ProtoToJson(message); }

int ReportRpcError(const GlobalOptions& options, const std::string& action,
                   const grpc::Status& status) {
  const int exit_code = ExitCodeForStatus(status.error_code());
  std::string message = status.error_message();
  if (status.error_code() == grpc::StatusCode::UNAVAILABLE ||
      status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED) {
    message = absl::StrCat(message, " (is swarmplan-server running at ", options.server,
                           "? set --server or SWARMPLAN_SERVER)");
  }
  std::cerr << "swarmplan: " << action << ": " << StatusCodeName(status.error_code()) << ": "
            << message << "\n";
  if (options.json) {
    nlohmann::json error = {{"error",
                             {{"action", action},
                              {"code", StatusCodeName(status.error_code())},
                              {"message", message},
                              {"exit_code", exit_code}}}};
    std::cout << error.dump(2) << "\n";
  }
  return exit_code;
}

int ReportError(const GlobalOptions& options, int exit_code, const std::string& message) {
  std::cerr << "swarmplan: " << message << "\n";
  if (options.json) {
    nlohmann::json error = {{"error", {{"message", message}, {"exit_code", exit_code}}}};
    std::cout << error.dump(2) << "\n";
  }
  return exit_code;
}

int ReportLocalError(const GlobalOptions& options, const absl::Status& status) {
  return ReportError(options, kExitUsage, std::string(status.message()));
}

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return absl::StrFormat("%.6g", value);
}

std::string FormatSeconds(double seconds) {
  if (!std::isfinite(seconds)) return "?";
  if (seconds < 1.0) return absl::StrFormat("%.0fms", seconds * 1000.0);
  if (seconds < 60.0) return absl::StrFormat("%.1fs", seconds);
  const int total = static_cast<int>(std::lround(seconds));
  if (total < 3600) return absl::StrFormat("%dm%02ds", total / 60, total % 60);
  return absl::StrFormat("%dh%02dm", total / 3600, (total % 3600) / 60);
}

double DurationSeconds(const google::protobuf::Duration& duration) {
  return static_cast<double>(duration.seconds()) + duration.nanos() * 1e-9;
}

std::string FormatDuration(const google::protobuf::Duration& duration) {
  return FormatSeconds(DurationSeconds(duration));
}

std::string FormatTimestamp(const google::protobuf::Timestamp& timestamp) {
  if (timestamp.seconds() == 0 && timestamp.nanos() == 0) return "";
  const absl::Time time = absl::FromUnixSeconds(timestamp.seconds());
  return absl::FormatTime("%Y-%m-%d %H:%M:%S", time, absl::LocalTimeZone());
}

std::string FormatPoint(const v1::Point& point, bool with_z) {
  if (with_z) {
    return absl::StrCat("(", FormatNumber(point.x()), ", ", FormatNumber(point.y()), ", ",
                        FormatNumber(point.z()), ")");
  }
  return absl::StrCat("(", FormatNumber(point.x()), ", ", FormatNumber(point.y()), ")");
}

std::string FormatParamValue(const v1::ParamValue& value) {
  switch (value.kind_case()) {
    case v1::ParamValue::kBoolValue:
      return value.bool_value() ? "true" : "false";
    case v1::ParamValue::kIntValue:
      return absl::StrCat(value.int_value());
    case v1::ParamValue::kDoubleValue:
      return FormatNumber(value.double_value());
    case v1::ParamValue::kStringValue:
      return value.string_value();
    default:
      return "";
  }
}

std::string MapKindName(v1::MapKind kind) {
  switch (kind) {
    case v1::MAP_KIND_OCCUPANCY_GRID:
      return "occupancy-grid";
    case v1::MAP_KIND_SHAPE_WORLD:
      return "shape-world";
    case v1::MAP_KIND_TERRAIN:
      return "terrain";
    default:
      return "unspecified";
  }
}

namespace {

const std::map<v1::JobState, std::string>& JobStateNameTable() {
  static const auto* names = new std::map<v1::JobState, std::string>{
      {v1::JOB_STATE_QUEUED, "queued"},
      {v1::JOB_STATE_RUNNING, "running"},
      {v1::JOB_STATE_SUCCEEDED, "succeeded"},
      {v1::JOB_STATE_NO_PATH_FOUND, "no-path-found"},
      {v1::JOB_STATE_CANCELLED, "cancelled"},
      {v1::JOB_STATE_DEADLINE_EXCEEDED, "deadline-exceeded"},
      {v1::JOB_STATE_FAILED, "failed"},
  };
  return *names;
}

}  // namespace

std::string JobStateName(v1::JobState state) {
  auto it = JobStateNameTable().find(state);
  return it == JobStateNameTable().end() ? "unspecified" : it->second;
}

v1::JobState ParseJobState(const std::string& name) {
  std::string wanted = absl::StrReplaceAll(absl::AsciiStrToLower(name), {{"_", "-"}});
  if (absl::StartsWith(wanted, "job-state-")) wanted = wanted.substr(10);
  for (const auto& [state, state_name] : JobStateNameTable()) {
    if (state_name == wanted) return state;
  }
  return v1::JOB_STATE_UNSPECIFIED;
}

std::vector<std::string> JobStateNames() {
  std::vector<std::string> names;
  for (const auto& [state, name] : JobStateNameTable()) names.push_back(name);
  return names;
}

std::string ParameterTypeName(v1::ParameterType type) {
  switch (type) {
    case v1::PARAMETER_TYPE_BOOL:
      return "bool";
    case v1::PARAMETER_TYPE_INT:
      return "int";
    case v1::PARAMETER_TYPE_DOUBLE:
      return "double";
    case v1::PARAMETER_TYPE_ENUM:
      return "enum";
    default:
      return "?";
  }
}

std::string FormatLabels(const google::protobuf::Map<std::string, std::string>& labels) {
  std::map<std::string, std::string> sorted(labels.begin(), labels.end());
  return absl::StrJoin(sorted, ",", absl::PairFormatter("="));
}

}  // namespace swarmplan::client
