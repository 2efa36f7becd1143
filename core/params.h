#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "absl/status/statusor.h"

namespace swarmplan {

using ParamValue = std::variant<bool, int64_t, double, std::string>;
// Parameters by name, as a request gives them (unvalidated) or as a planner resolved them.
using ParamValues = std::map<std::string, ParamValue>;

enum class ParamType { kBool, kInt, kDouble, kEnum };
const char* ParamTypeName(ParamType type);
std::string FormatParamValue(const ParamValue& value);

// One parameter of a planner, declared as data so tools can list and validate it.
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::kDouble;
  ParamValue default_value;
  std::optional<double> min;         // inclusive, for kInt and kDouble
  std::optional<double> max;         // inclusive, for kInt and kDouble
  std::vector<std::string> choices;  // for kEnum
  std::string unit;                  // "cells", "iterations", "" for dimensionless
  std::string description;
  bool ours = false;  // default chosen by us, not given by the paper
  // The parameter sizes a population (beetles, particles, bacteria, fish, ants, ...): servers
  // cap it by their population limit without knowing the planner.
  bool population_size = false;

  static ParamSpec Int(std::string name, int64_t def, std::optional<double> min,
                       std::optional<double> max, std::string unit, std::string description);
  static ParamSpec Double(std::string name, double def, std::optional<double> min,
                          std::optional<double> max, std::string unit, std::string description);
  static ParamSpec Bool(std::string name, bool def, std::string description);
  static ParamSpec Enum(std::string name, std::string def, std::vector<std::string> choices,
                        std::string description);
  ParamSpec& Ours() {
    ours = true;
    return *this;
  }
  ParamSpec& PopulationSize() {
    population_size = true;
    return *this;
  }
};

// Validated parameters: every declared parameter present with the right type and in range.
class ParamSet {
 public:
  // Rejects unknown names, wrong types and out-of-range values, naming the parameter. Integers
  // are accepted for double parameters; integral doubles for integer parameters.
  static absl::StatusOr<ParamSet> Resolve(const std::vector<ParamSpec>& specs,
                                          const ParamValues& given);

  int64_t Int(const std::string& name) const;
  double Double(const std::string& name) const;
  bool Bool(const std::string& name) const;
  const std::string& Enum(const std::string& name) const;
  const ParamValues& values() const { return values_; }

 private:
  ParamValues values_;
};

}  // namespace swarmplan
