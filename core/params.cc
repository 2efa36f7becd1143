#include "core/params.h"

#include <cmath>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace swarmplan {

const char* ParamTypeName(ParamType type) {
  switch (type) {
    case ParamType::kBool:
      return "bool";
    case ParamType::kInt:
      return "int";
    case ParamType::kDouble:
      return "double";
    case ParamType::kEnum:
      return "enum";
  }
  return "unknown";
}

std::string FormatParamValue(const ParamValue& value) {
  struct Formatter {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(int64_t i) const { return absl::StrCat(i); }
    std::string operator()(double d) const { return absl::StrCat(d); }
    std::string operator()(const std::string& s) const { return s; }
  };
  return std::visit(Formatter{}, value);
}

ParamSpec ParamSpec::Int(std::string name, int64_t def, std::optional<double> min,
                         std::optional<double> max, std::string unit, std::string description) {
  return ParamSpec{std::move(name), ParamType::kInt,       def, min, max, {},
                   std::move(unit), std::move(description)};
}

ParamSpec ParamSpec::Double(std::string name, double def, std::optional<double> min,
                            std::optional<double> max, std::string unit, std::string description) {
  return ParamSpec{std::move(name), ParamType::kDouble,    def, min, max, {},
                   std::move(unit), std::move(description)};
}

ParamSpec ParamSpec::Bool(std::string name, bool def, std::string description) {
  return ParamSpec{std::move(name),       ParamType::kBool, def, std::nullopt, std::nullopt, {}, "",
                   std::move(description)};
}

ParamSpec ParamSpec::Enum(std::string name, std::string def, std::vector<std::string> choices,
                          std::string description) {
  return ParamSpec{std::move(name),
                   ParamType::kEnum,
                   std::move(def),
                   std::nullopt,
                   std::nullopt,
                   std::move(choices),
                   "",
                   std::move(description)};
}

namespace {

absl::Status OutOfRange(const ParamSpec& spec, double v) {
  return absl::InvalidArgumentError(absl::StrCat(
      "parameter '", spec.name, "': value ", v, " is out of range [",
      spec.min ? absl::StrCat(*spec.min) : "-inf", ", ", spec.max ? absl::StrCat(*spec.max) : "inf",
      "]", spec.unit.empty() ? "" : absl::StrCat(" ", spec.unit)));
}

absl::Status CheckRange(const ParamSpec& spec, double v) {
  if (!std::isfinite(v)) {
    return absl::InvalidArgumentError(
        absl::StrCat("parameter '", spec.name, "': value must be finite"));
  }
  if ((spec.min && v < *spec.min) || (spec.max && v > *spec.max)) return OutOfRange(spec, v);
  return absl::OkStatus();
}

absl::Status WrongType(const ParamSpec& spec, const ParamValue& given) {
  static constexpr const char* kGivenNames[] = {"bool", "int", "double", "string"};
  return absl::InvalidArgumentError(
      absl::StrCat("parameter '", spec.name, "': expected ", ParamTypeName(spec.type), ", got ",
                   kGivenNames[given.index()], " ", FormatParamValue(given)));
}

absl::StatusOr<ParamValue> Coerce(const ParamSpec& spec, const ParamValue& given) {
  switch (spec.type) {
    case ParamType::kBool:
      if (const bool* b = std::get_if<bool>(&given)) return ParamValue(*b);
      return WrongType(spec, given);
    case ParamType::kInt: {
      int64_t v;
      if (const int64_t* i = std::get_if<int64_t>(&given)) {
        v = *i;
      } else if (const double* d = std::get_if<double>(&given);
                 d && std::isfinite(*d) && std::trunc(*d) == *d && std::fabs(*d) < 9e15) {
        v = static_cast<int64_t>(*d);
      } else {
        return WrongType(spec, given);
      }
      if (absl::Status s = CheckRange(spec, static_cast<double>(v)); !s.ok()) return s;
      return ParamValue(v);
    }
    case ParamType::kDouble: {
      double v;
      if (const double* d = std::get_if<double>(&given)) {
        v = *d;
      } else if (const int64_t* i = std::get_if<int64_t>(&given)) {
        v = static_cast<double>(*i);
      } else {
        return WrongType(spec, given);
      }
      if (absl::Status s = CheckRange(spec, v); !s.ok()) return s;
      return ParamValue(v);
    }
    case ParamType::kEnum: {
      const std::string* s = std::get_if<std::string>(&given);
      if (s == nullptr) return WrongType(spec, given);
      for (const std::string& choice : spec.choices) {
        if (choice == *s) return ParamValue(*s);
      }
      return absl::InvalidArgumentError(absl::StrCat("parameter '", spec.name, "': '", *s,
                                                     "' is not one of ",
                                                     absl::StrJoin(spec.choices, ", ")));
    }
  }
  return WrongType(spec, given);
}

}  // namespace

absl::StatusOr<ParamSet> ParamSet::Resolve(const std::vector<ParamSpec>& specs,
                                           const ParamValues& given) {
  for (const auto& [name, value] : given) {
    bool known = false;
    for (const ParamSpec& spec : specs) known = known || spec.name == name;
    if (!known) {
      std::vector<std::string> names;
      for (const ParamSpec& spec : specs) names.push_back(spec.name);
      return absl::InvalidArgumentError(
          absl::StrCat("unknown parameter '", name, "'; this planner accepts: ",
                       names.empty() ? std::string("no parameters") : absl::StrJoin(names, ", ")));
    }
  }
  ParamSet set;
  for (const ParamSpec& spec : specs) {
    auto it = given.find(spec.name);
    if (it == given.end()) {
      set.values_[spec.name] = spec.default_value;
      continue;
    }
    absl::StatusOr<ParamValue> value = Coerce(spec, it->second);
    if (!value.ok()) return value.status();
    set.values_[spec.name] = *std::move(value);
  }
  return set;
}

int64_t ParamSet::Int(const std::string& name) const { return std::get<int64_t>(values_.at(name)); }
double ParamSet::Double(const std::string& name) const {
  return std::get<double>(values_.at(name));
}
bool ParamSet::Bool(const std::string& name) const { return std::get<bool>(values_.at(name)); }
const std::string& ParamSet::Enum(const std::string& name) const {
  return std::get<std::string>(values_.at(name));
}

}  // namespace swarmplan
