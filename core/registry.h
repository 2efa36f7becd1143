#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/map.h"
#include "core/params.h"
#include "core/planner.h"

namespace swarmplan {

// How a planner represents a path; tells which maps it can use and how.
enum class Encoding { kGridNodes, kWaypoints, kColumns, kVertexSubset, kExact };
const char* EncodingName(Encoding encoding);

struct PlannerInfo {
  std::string id;           // "astar", "aem-bso", ...
  std::string description;  // one paragraph: the method, and what is ours rather than the paper's
  std::string seed_paper;   // the paper it comes from, or "" for classics
  Encoding encoding = Encoding::kExact;
  std::vector<MapKind> map_kinds;
  std::vector<ParamSpec> params;
  std::function<std::unique_ptr<Planner>(const ParamSet&)> factory;

  bool Supports(MapKind kind) const;
};

// The catalogue of planners: id -> description, schema, factory. A value, built by
// DefaultRegistry(); no global state.
class Registry {
 public:
  // Fails when the id is taken or the info is incomplete.
  absl::Status Register(PlannerInfo info);

  // nullptr when unknown.
  const PlannerInfo* Find(const std::string& id) const;
  // NOT_FOUND naming the valid ids when unknown.
  absl::StatusOr<const PlannerInfo*> Get(const std::string& id) const;
  const std::vector<PlannerInfo>& planners() const { return planners_; }
  std::vector<std::string> Ids() const;

  // Validates the parameters against the schema and builds the planner.
  absl::StatusOr<std::unique_ptr<Planner>> Create(const std::string& id,
                                                  const ParamValues& params) const;

 private:
  std::vector<PlannerInfo> planners_;
};

// Every planner swarmplan ships. New planners appear everywhere by being registered here.
const Registry& DefaultRegistry();

}  // namespace swarmplan
