#pragma once

#include <string>
#include <utility>

#include "absl/status/statusor.h"
#include "swarmplan/v1/algorithms.pb.h"
#include "swarmplan/v1/common.pb.h"

// Parsing of the values given on the command line. Errors name the flag.
namespace swarmplan::client {

// "x,y" or "x,y,z".
absl::StatusOr<v1::Point> ParsePoint(const std::string& flag, const std::string& text);

// "key=value" (the key non-empty).
absl::StatusOr<std::pair<std::string, std::string>> ParseKeyValue(const std::string& flag,
                                                                  const std::string& text);

// A parameter value typed by its schema; without one (nullptr): true/false, integer, number,
// else a string.
absl::StatusOr<v1::ParamValue> ParseParamValue(const std::string& name, const std::string& text,
                                               const v1::ParameterSpec* spec);

// Seconds: "30", "1.5s", "500ms", "2m", "1h".
absl::StatusOr<double> ParseSeconds(const std::string& flag, const std::string& text);

}  // namespace swarmplan::client
