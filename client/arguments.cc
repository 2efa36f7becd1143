#include "client/arguments.h"

#include <cmath>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"

namespace swarmplan::client {
namespace {

bool ParseFiniteDouble(const std::string& text, double* value) {
  return absl::SimpleAtod(text, value) && std::isfinite(*value);
}

}  // namespace

absl::StatusOr<v1::Point> ParsePoint(const std::string& flag, const std::string& text) {
  std::vector<std::string> parts = absl::StrSplit(text, ',');
  double values[3] = {0.0, 0.0, 0.0};
  bool ok = parts.size() == 2 || parts.size() == 3;
  for (size_t i = 0; ok && i < parts.size(); ++i) {
    ok = ParseFiniteDouble(std::string(absl::StripAsciiWhitespace(parts[i])), &values[i]);
  }
  if (!ok) {
    return absl::InvalidArgumentError(
        absl::StrCat(flag, ": '", text, "' is not a point; expected x,y or x,y,z"));
  }
  v1::Point point;
  point.set_x(values[0]);
  point.set_y(values[1]);
  point.set_z(values[2]);
  return point;
}

absl::StatusOr<std::pair<std::string, std::string>> ParseKeyValue(const std::string& flag,
                                                                  const std::string& text) {
  const size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) {
    return absl::InvalidArgumentError(absl::StrCat(flag, ": '", text, "' is not NAME=VALUE"));
  }
  return std::make_pair(text.substr(0, equals), text.substr(equals + 1));
}

absl::StatusOr<v1::ParamValue> ParseParamValue(const std::string& name, const std::string& text,
                                               const v1::ParameterSpec* spec) {
  v1::ParamValue value;
  const std::string lower = absl::AsciiStrToLower(text);
  auto wrong = [&](const char* expected) {
    return absl::InvalidArgumentError(
        absl::StrCat("--param ", name, ": '", text, "' is not ", expected));
  };
  const v1::ParameterType type = spec ? spec->type() : v1::PARAMETER_TYPE_UNSPECIFIED;
  int64_t integer = 0;
  double number = 0.0;
  switch (type) {
    case v1::PARAMETER_TYPE_BOOL:
      if (lower == "true" || lower == "1" || lower == "yes") {
        value.set_bool_value(true);
      } else if (lower == "false" || lower == "0" || lower == "no") {
        value.set_bool_value(false);
      } else {
        return wrong("a bool (true or false)");
      }
      return value;
    case v1::PARAMETER_TYPE_INT:
      if (!absl::SimpleAtoi(text, &integer)) return wrong("an integer");
      value.set_int_value(integer);
      return value;
    case v1::PARAMETER_TYPE_DOUBLE:
      if (!ParseFiniteDouble(text, &number)) return wrong("a number");
      value.set_double_value(number);
      return value;
    case v1::PARAMETER_TYPE_ENUM:
      value.set_string_value(text);
      return value;
    default:
      break;
  }
  if (lower == "true" || lower == "false") {
    value.set_bool_value(lower == "true");
  } else if (absl::SimpleAtoi(text, &integer)) {
    value.set_int_value(integer);
  } else if (ParseFiniteDouble(text, &number)) {
    value.set_double_value(number);
  } else {
    value.set_string_value(text);
  }
  return value;
}

absl::StatusOr<double> ParseSeconds(const std::string& flag, const std::string& text) {
  std::string number = std::string(absl::StripAsciiWhitespace(text));
  double scale = 1.0;
  if (absl::EndsWith(number, "ms")) {
    scale = 0.001;
    number.resize(number.size() - 2);
  } else if (absl::EndsWith(number, "s")) {
    number.resize(number.size() - 1);
  } else if (absl::EndsWith(number, "m")) {
    scale = 60.0;
    number.resize(number.size() - 1);
  } else if (absl::EndsWith(number, "h")) {
    scale = 3600.0;
    number.resize(number.size() - 1);
  }
  double value = 0.0;
  if (!ParseFiniteDouble(number, &value) || value < 0.0) {
    return absl::InvalidArgumentError(absl::StrCat(
        flag, ": '", text, "' is not a duration; expected seconds like 30, 1.5s, 500ms, 2m"));
  }
  return value * scale;
}

}  // namespace swarmplan::client
