#include "core/registry.h"

#include <algorithm>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace swarmplan {

const char* EncodingName(Encoding encoding) {
  switch (encoding) {
    case Encoding::kGridNodes:
      return "grid-nodes";
    case Encoding::kWaypoints:
      return "waypoints";
    case Encoding::kColumns:
      return "columns";
    case Encoding::kVertexSubset:
      return "vertex-subset";
    case Encoding::kExact:
      return "exact";
  }
  return "unknown";
}

bool PlannerInfo::Supports(MapKind kind) const {
  return std::find(map_kinds.begin(), map_kinds.end(), kind) != map_kinds.end();
}

absl::Status Registry::Register(PlannerInfo info) {
  if (info.id.empty() || !info.factory || info.map_kinds.empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat("planner '", info.id, "' needs an id, a factory and at least one map kind"));
  }
  if (Find(info.id) != nullptr) {
    return absl::AlreadyExistsError(absl::StrCat("planner '", info.id, "' is already registered"));
  }
  // Defaults must satisfy the planner's own schema.
  ParamValues defaults;
  for (const ParamSpec& spec : info.params) defaults[spec.name] = spec.default_value;
  if (absl::StatusOr<ParamSet> set = ParamSet::Resolve(info.params, defaults); !set.ok()) {
    return absl::InvalidArgumentError(
        absl::StrCat("planner '", info.id, "' has an invalid default: ", set.status().message()));
  }
  planners_.push_back(std::move(info));
  return absl::OkStatus();
}

const PlannerInfo* Registry::Find(const std::string& id) const {
  for (const PlannerInfo& info : planners_) {
    if (info.id == id) return &info;
  }
  return nullptr;
}

std::vector<std::string> Registry::Ids() const {
  std::vector<std::string> ids;
  for (const PlannerInfo& info : planners_) ids.push_back(info.id);
  return ids;
}

absl::StatusOr<const PlannerInfo*> Registry::Get(const std::string& id) const {
  if (const PlannerInfo* info = Find(id)) return info;
  return absl::NotFoundError(
      absl::StrCat("unknown algorithm '", id, "'; available: ", absl::StrJoin(Ids(), ", ")));
}

absl::StatusOr<std::unique_ptr<Planner>> Registry::Create(const std::string& id,
                                                          const ParamValues& params) const {
  absl::StatusOr<const PlannerInfo*> info = Get(id);
  if (!info.ok()) return info.status();
  absl::StatusOr<ParamSet> set = ParamSet::Resolve((*info)->params, params);
  if (!set.ok()) return set.status();
  return (*info)->factory(*set);
}

}  // namespace swarmplan
