#pragma once

#include "core/map/map.h"
#include "core/params.h"
#include "core/planner.h"
#include "core/registry.h"
#include "core/run.h"
#include "google/protobuf/duration.pb.h"
#include "google/protobuf/timestamp.pb.h"
#include "swarmplan/v1/algorithms.pb.h"
#include "swarmplan/v1/jobs.pb.h"

namespace swarmplan::server {

// Conversions between core values and swarmplan.v1 messages. Pure functions.
google::protobuf::Timestamp ToProto(absl::Time t);
absl::Time FromProto(const google::protobuf::Timestamp& t);
google::protobuf::Duration ToProtoDuration(absl::Duration d);
absl::Duration FromProto(const google::protobuf::Duration& d);

v1::Point ToProto(const Point3& p);
Point3 FromProto(const v1::Point& p);
// Unset weights are 1, as the .proto says.
FleetObjective FromProto(const v1::PathPreferences& p);
VehicleLimits FromProto(const v1::VehicleLimits& v);
v1::MapKind ToProto(MapKind kind);

v1::ParamValue ToProto(const ParamValue& value);
// INVALID_ARGUMENT naming the parameter when no member is set.
absl::StatusOr<ParamValues> FromProto(
    const google::protobuf::Map<std::string, v1::ParamValue>& values);

v1::IterationStats ToProto(const IterationStats& stats);
v1::PlanResult ToProto(const PlanResult& result);
v1::Algorithm ToProto(const PlannerInfo& info);

}  // namespace swarmplan::server
