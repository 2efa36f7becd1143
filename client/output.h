#pragma once

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "client/connection.h"
#include "google/protobuf/duration.pb.h"
#include "google/protobuf/message.h"
#include "google/protobuf/timestamp.pb.h"
#include "grpcpp/support/status.h"
#include "swarmplan/v1/algorithms.pb.h"
#include "swarmplan/v1/jobs.pb.h"
#include "swarmplan/v1/maps.pb.h"

// What every command shares to print results: tables, key/value blocks, JSON, errors, and the
// formatting of the API's values.
namespace swarmplan::client {

// A text table: columns padded to their widest cell.
class Table {
 public:
  explicit Table(std::vector<std::string> headers) : headers_(std::move(headers)) {}
  void AddRow(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  bool empty() const { return rows_.empty(); }
  void Print(std::ostream& out) const;

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

using KeyValues = std::vector<std::pair<std::string, std::string>>;
// "key:   value" lines, keys padded to the widest.
void PrintKeyValues(std::ostream& out, const KeyValues& rows);

// The message as JSON with the .proto field names, every field present; on one line unless
// `pretty`.
std::string ProtoToJson(const google::protobuf::Message& message, bool pretty = true);
// Prints ProtoToJson to stdout.
void PrintJson(const google::protobuf::Message& message);

// Reports a failed RPC on stderr (and as {"error": ...} on stdout with --json); returns the
// exit code for it.
int ReportRpcError(const GlobalOptions& options, const std::string& action,
                   const grpc::Status& status);
// Reports any other error with the given exit code; returns it.
int ReportError(const GlobalOptions& options, int exit_code, const std::string& message);
// ReportError(kExitUsage, ...) for a local problem (unreadable file, bad value).
int ReportLocalError(const GlobalOptions& options, const absl::Status& status);

// Values of the API, formatted for people.
std::string FormatNumber(double value);  // %.6g, "inf", "nan"
std::string FormatSeconds(double seconds);
double DurationSeconds(const google::protobuf::Duration& duration);
std::string FormatDuration(const google::protobuf::Duration& duration);
std::string FormatTimestamp(const google::protobuf::Timestamp& timestamp);  // "" when unset
std::string FormatPoint(const v1::Point& point, bool with_z);
std::string FormatParamValue(const v1::ParamValue& value);
std::string MapKindName(v1::MapKind kind);     // "occupancy-grid", ...
std::string JobStateName(v1::JobState state);  // "succeeded", ...
std::string ParameterTypeName(v1::ParameterType type);
std::string FormatLabels(const google::protobuf::Map<std::string, std::string>& labels);
// Parses "queued", "no-path-found" (or "no_path_found"), ...; UNSPECIFIED when unknown.
v1::JobState ParseJobState(const std::string& name);
std::vector<std::string> JobStateNames();

}  // namespace swarmplan::client
