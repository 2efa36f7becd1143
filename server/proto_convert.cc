#include "server/proto_convert.h"

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"

namespace swarmplan::server {

google::protobuf::Timestamp ToProto(absl::Time t) {
  google::protobuf::Timestamp ts;
  if (t == absl::InfinitePast() || t == absl::InfiniteFuture()) return ts;
  const int64_t ns = absl::ToUnixNanos(t);
  ts.set_seconds(ns / 1000000000);
  ts.set_nanos(static_cast<int32_t>(ns % 1000000000));
  return ts;
}

absl::Time FromProto(const google::protobuf::Timestamp& t) {
  return absl::FromUnixSeconds(t.seconds()) + absl::Nanoseconds(t.nanos());
}

google::protobuf::Duration ToProtoDuration(absl::Duration d) {
  google::protobuf::Duration out;
  if (d == absl::InfiniteDuration()) return out;
  const int64_t ns = absl::ToInt64Nanoseconds(d);
  out.set_seconds(ns / 1000000000);
  out.set_nanos(static_cast<int32_t>(ns % 1000000000));
  return out;
}

absl::Duration FromProto(const google::protobuf::Duration& d) {
  return absl::Seconds(d.seconds()) + absl::Nanoseconds(d.nanos());
}

v1::Point ToProto(const Point3& p) {
  v1::Point out;
  out.set_x(p.x());
  out.set_y(p.y());
  out.set_z(p.z());
  return out;
}

Point3 FromProto(const v1::Point& p) { return Point3(p.x(), p.y(), p.z()); }

FleetObjective FromProto(const v1::PathPreferences& p) {
  FleetObjective fleet;
  fleet.preferred_clearance = p.preferred_clearance();
  fleet.turning_radius = p.turning_radius();
  if (p.has_clearance_weight()) fleet.clearance_weight = p.clearance_weight();
  if (p.has_curvature_weight()) fleet.curvature_weight = p.curvature_weight();
  return fleet;
}

v1::MapKind ToProto(MapKind kind) {
  switch (kind) {
    case MapKind::kOccupancyGrid:
      return v1::MAP_KIND_OCCUPANCY_GRID;
    case MapKind::kShapeWorld:
      return v1::MAP_KIND_SHAPE_WORLD;
    case MapKind::kTerrain:
      return v1::MAP_KIND_TERRAIN;
  }
  return v1::MAP_KIND_UNSPECIFIED;
}

v1::ParamValue ToProto(const ParamValue& value) {
  v1::ParamValue out;
  if (const bool* b = std::get_if<bool>(&value)) out.set_bool_value(*b);
  if (const int64_t* i = std::get_if<int64_t>(&value)) out.set_int_value(*i);
  if (const double* d = std::get_if<double>(&value)) out.set_double_value(*d);
  if (const std::string* s = std::get_if<std::string>(&value)) out.set_string_value(*s);
  return out;
}

absl::StatusOr<ParamValues> FromProto(
    const google::protobuf::Map<std::string, v1::ParamValue>& values) {
  ParamValues out;
  for (const auto& [name, value] : values) {
    switch (value.kind_case()) {
      case v1::ParamValue::kBoolValue:
        out[name] = value.bool_value();
        break;
      case v1::ParamValue::kIntValue:
        out[name] = value.int_value();
        break;
      case v1::ParamValue::kDoubleValue:
        out[name] = value.double_value();
        break;
      case v1::ParamValue::kStringValue:
        out[name] = value.string_value();
        break;
      case v1::ParamValue::KIND_NOT_SET:
        return absl::InvalidArgumentError(absl::StrCat("parameters['", name, "']: no value set"));
    }
  }
  return out;
}

v1::IterationStats ToProto(const IterationStats& stats) {
  v1::IterationStats out;
  out.set_iteration(stats.iteration);
  out.set_best_fitness(stats.best_fitness);
  out.set_mean_fitness(stats.mean_fitness);
  out.set_evaluations(stats.evaluations);
  *out.mutable_elapsed() = ToProtoDuration(stats.elapsed);
  out.set_feasible(stats.feasible);
  return out;
}

namespace {

v1::PathMetrics ToProto(const PathMetrics& m) {
  v1::PathMetrics out;
  out.set_length(m.length);
  out.set_min_clearance(m.min_clearance);
  out.set_max_curvature(m.max_curvature);
  out.set_turning_points(m.turning_points);
  out.set_collision_free(m.collision_free);
  return out;
}

const char* StopReasonId(StopReason reason) {
  switch (reason) {
    case StopReason::kNone:
      return "none";
    case StopReason::kCancelled:
      return "cancelled";
    case StopReason::kDeadline:
      return "deadline";
    case StopReason::kIterationCap:
      return "iteration-cap";
  }
  return "none";
}

v1::ObjectiveTerms ToProto(const FleetTerms& t) {
  v1::ObjectiveTerms out;
  out.set_length(t.length);
  out.set_clearance(t.clearance);
  out.set_curvature(t.curvature);
  out.set_violation(t.violation);
  out.set_total(t.Total());
  return out;
}

}  // namespace

VehicleLimits FromProto(const v1::VehicleLimits& v) {
  VehicleLimits vehicle;
  vehicle.max_speed = v.max_speed();
  vehicle.max_acceleration = v.max_acceleration();
  vehicle.max_yaw_rate = v.max_yaw_rate();
  return vehicle;
}

v1::PlanResult ToProto(const PlanResult& r) {
  v1::PlanResult out;
  out.set_algorithm(r.algorithm);
  out.set_found(r.found);
  for (const Point3& p : r.raw_path) *out.add_raw_path() = ToProto(p);
  for (const Point3& p : r.smoothed_path) *out.add_smoothed_path() = ToProto(p);
  *out.mutable_raw_metrics() = ToProto(r.raw_metrics);
  *out.mutable_smoothed_metrics() = ToProto(r.smoothed_metrics);
  out.set_smoothing(r.smoothing);
  out.set_smoothing_collision_free(r.smoothing_collision_free);
  out.set_fitness(r.fitness);
  out.set_iterations(r.iterations);
  out.set_evaluations(r.evaluations);
  out.set_best_iteration(r.best_iteration);
  out.set_stop_reason(StopReasonId(r.stop_reason));
  *out.mutable_wall_time() = ToProtoDuration(r.wall_time);
  *out.mutable_cpu_time() = ToProtoDuration(r.cpu_time);
  out.set_seed(r.seed);
  for (const auto& [name, value] : r.resolved_params) {
    (*out.mutable_resolved_parameters())[name] = ToProto(value);
  }
  for (const IterationStats& s : r.convergence) *out.add_convergence() = ToProto(s);
  out.set_optimum_planner(r.optimum.planner);
  if (r.optimum.known) {
    out.set_optimum_length(r.optimum.length);
    out.set_optimum_cost(r.optimum.cost);
    if (r.found) out.set_optimality_ratio(r.optimality_ratio);
  } else {
    out.set_optimum_note(r.optimum.reason);
  }
  for (const PlanResult::Alternative& a : r.alternatives) {
    v1::AlternativePath* alternative = out.add_alternatives();
    for (const Point3& p : a.path) *alternative->add_path() = ToProto(p);
    *alternative->mutable_metrics() = ToProto(a.metrics);
    alternative->set_fitness(a.fitness);
    if (r.optimum.known) alternative->set_optimality_ratio(a.optimality_ratio);
  }
  if (r.objective) *out.mutable_objective() = ToProto(*r.objective);
  if (r.seed_objective) *out.mutable_seed_objective() = ToProto(*r.seed_objective);
  out.set_via_points_reached(r.via_points_reached);
  for (const PlanResult::Leg& leg : r.legs) {
    v1::LegResult* l = out.add_legs();
    l->set_found(leg.found);
    *l->mutable_metrics() = ToProto(leg.metrics);
    l->set_fitness(leg.fitness);
    l->set_iterations(leg.iterations);
  }
  if (r.timed_path) {
    v1::TimedPath* timed = out.mutable_timed_path();
    for (const TimedPoint& p : r.timed_path->points) {
      v1::TimedPoint* point = timed->add_points();
      *point->mutable_point() = ToProto(p.point);
      point->set_time(p.time);
      point->set_speed(p.speed);
    }
    timed->set_duration(r.timed_path->duration);
  }
  return out;
}

v1::Algorithm ToProto(const PlannerInfo& info) {
  v1::Algorithm out;
  out.set_id(info.id);
  out.set_description(info.description);
  out.set_seed_paper(info.seed_paper);
  out.set_encoding(EncodingName(info.encoding));
  for (MapKind kind : info.map_kinds) out.add_map_kinds(ToProto(kind));
  for (const ParamSpec& spec : info.params) {
    v1::ParameterSpec* p = out.add_parameters();
    p->set_name(spec.name);
    switch (spec.type) {
      case ParamType::kBool:
        p->set_type(v1::PARAMETER_TYPE_BOOL);
        break;
      case ParamType::kInt:
        p->set_type(v1::PARAMETER_TYPE_INT);
        break;
      case ParamType::kDouble:
        p->set_type(v1::PARAMETER_TYPE_DOUBLE);
        break;
      case ParamType::kEnum:
        p->set_type(v1::PARAMETER_TYPE_ENUM);
        break;
    }
    *p->mutable_default_value() = ToProto(spec.default_value);
    if (spec.min) p->set_min(*spec.min);
    if (spec.max) p->set_max(*spec.max);
    for (const std::string& c : spec.choices) p->add_choices(c);
    p->set_unit(spec.unit);
    p->set_description(spec.description);
    p->set_default_is_ours(spec.ours);
    p->set_population_size(spec.population_size);
  }
  return out;
}

}  // namespace swarmplan::server
