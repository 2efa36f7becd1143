#include "client/vda5050_order.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"

namespace swarmplan::client {
namespace {

using nlohmann::json;

std::string Label(const v1::Job& job, const std::string& name) {
  const auto& labels = job.request().labels();
  const auto found = labels.find(name);
  return found == labels.end() ? std::string() : found->second;
}

}  // namespace

absl::StatusOr<json> Vda5050Order(const v1::Job& job, absl::Time now) {
  const v1::PlanResult& result = job.result();
  std::vector<v1::Point> points;
  std::vector<double> speeds;
  if (!result.timed_path().points().empty()) {
    for (const v1::TimedPoint& p : result.timed_path().points()) {
      points.push_back(p.point());
      speeds.push_back(p.speed());
    }
  } else {
    const auto& path = result.smoothed_path().empty() ? result.raw_path() : result.smoothed_path();
    points.assign(path.begin(), path.end());
  }
  if (points.empty()) {
    return absl::FailedPreconditionError(absl::StrCat("job ", job.id(), " has no path"));
  }
  for (const v1::Point& p : points) {
    if (p.z() != 0.0) {
      return absl::FailedPreconditionError(
          absl::StrCat("job ", job.id(),
                       ": a VDA 5050 order takes planar paths; this one has "
                       "heights (terrain)"));
    }
  }
  const v1::VehicleLimits& vehicle = job.request().vehicle();
  json nodes = json::array();
  json edges = json::array();
  for (size_t i = 0; i < points.size(); ++i) {
    const v1::Point& p = points[i];
    // The heading of the edge leaving the node (of the one arriving at the last node).
    const v1::Point& from = i + 1 < points.size() ? p : points[i > 0 ? i - 1 : 0];
    const v1::Point& to = i + 1 < points.size() ? points[i + 1] : p;
    json position = {{"x", p.x()}, {"y", p.y()}, {"mapId", job.request().map_id()}};
    if (from.x() != to.x() || from.y() != to.y()) {
      position["theta"] = std::atan2(to.y() - from.y(), to.x() - from.x());
    }
    nodes.push_back({{"nodeId", absl::StrCat("node-", i)},
                     {"sequenceId", 2 * i},
                     {"released", true},
                     {"nodePosition", position},
                     {"actions", json::array()}});
    if (i + 1 == points.size()) break;
    const double length = std::hypot(to.x() - from.x(), to.y() - from.y());
    json edge = {{"edgeId", absl::StrCat("edge-", i)},
                 {"sequenceId", 2 * i + 1},
                 {"released", true},
                 {"length", length},
                 {"actions", json::array()}};
    if (!speeds.empty() && vehicle.max_acceleration() > 0.0) {
      // The timing rises at max_acceleration from one point's speed, falls to the next's.
      const double v0 = speeds[i], v1 = speeds[i + 1];
      edge["maximumSpeed"] =
          std::min(vehicle.max_speed(),
                   std::sqrt(vehicle.max_acceleration() * length + 0.5 * (v0 * v0 + v1 * v1)));
    }
    edges.push_back(edge);
  }
  return json{{"headerId", 0},
              {"timestamp", absl::FormatTime("%Y-%m-%dT%H:%M:%E3SZ", now, absl::UTCTimeZone())},
              {"version", "3.0.0"},
              {"manufacturer", Label(job, "manufacturer")},
              {"serialNumber", Label(job, "serial_number")},
              {"orderId", job.id()},
              {"orderUpdateId", 0},
              {"nodes", nodes},
              {"edges", edges}};
}

}  // namespace swarmplan::client
