#include "client/path_files.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/time/clock.h"
#include "client/output.h"
#include "client/vda5050_order.h"
#include "nlohmann/json.hpp"

namespace swarmplan::client {
namespace {

using nlohmann::json;

const google::protobuf::RepeatedPtrField<v1::Point>& BestPath(const v1::PlanResult& result) {
  return result.smoothed_path().empty() ? result.raw_path() : result.smoothed_path();
}

json PointsToJson(const google::protobuf::RepeatedPtrField<v1::Point>& points, bool with_z) {
  json array = json::array();
  for (const v1::Point& p : points) {
    array.push_back(with_z ? json::array({p.x(), p.y(), p.z()}) : json::array({p.x(), p.y()}));
  }
  return array;
}

bool HasZ(const google::protobuf::RepeatedPtrField<v1::Point>& points) {
  for (const v1::Point& p : points) {
    if (p.z() != 0.0) return true;
  }
  return false;
}

absl::StatusOr<std::vector<v1::Point>> PointsFromJson(const json& array, const std::string& file) {
  if (!array.is_array()) {
    return absl::InvalidArgumentError(absl::StrCat(file, ": the path is not a JSON array"));
  }
  std::vector<v1::Point> points;
  for (size_t i = 0; i < array.size(); ++i) {
    const json& item = array[i];
    v1::Point point;
    if (item.is_array() && (item.size() == 2 || item.size() == 3) && item[0].is_number() &&
        item[1].is_number()) {
      point.set_x(item[0].get<double>());
      point.set_y(item[1].get<double>());
      if (item.size() == 3 && item[2].is_number()) point.set_z(item[2].get<double>());
    } else if (item.is_object() && item.contains("x") && item.contains("y") &&
               item["x"].is_number() && item["y"].is_number()) {
      point.set_x(item["x"].get<double>());
      point.set_y(item["y"].get<double>());
      if (item.contains("z") && item["z"].is_number()) point.set_z(item["z"].get<double>());
    } else {
      return absl::InvalidArgumentError(
          absl::StrCat(file, ": point ", i, " is neither [x, y(, z)] nor {\"x\", \"y\"}"));
    }
    points.push_back(point);
  }
  return points;
}

// The first LineString of a GeoJSON object, or nullptr.
const json* FindLineString(const json& object) {
  if (!object.is_object()) return nullptr;
  const std::string type = object.value("type", "");
  if (type == "LineString" && object.contains("coordinates")) return &object["coordinates"];
  if (type == "Feature" && object.contains("geometry")) return FindLineString(object["geometry"]);
  if (type == "FeatureCollection" && object.contains("features") && object["features"].is_array()) {
    for (const json& feature : object["features"]) {
      if (const json* found = FindLineString(feature)) return found;
    }
  }
  return nullptr;
}

absl::StatusOr<PathFile> ParseJsonPath(const std::string& file, const std::string& text) {
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) {
    return absl::InvalidArgumentError(absl::StrCat(file, ": not valid JSON"));
  }
  PathFile path;
  path.label = std::filesystem::path(file).stem().string();
  const json* points = nullptr;
  json order_points;
  if (document.is_array()) {
    points = &document;
  } else if (document.is_object() && document.contains("path")) {
    points = &document["path"];
    if (document.contains("job_id") && document["job_id"].is_string()) {
      path.label = document["job_id"].get<std::string>();
    }
  } else if (document.is_object() && document.contains("nodes") && document["nodes"].is_array()) {
    // A VDA 5050 order: its nodes' positions.
    order_points = json::array();
    for (const json& node : document["nodes"]) {
      if (node.is_object() && node.contains("nodePosition")) {
        order_points.push_back(node["nodePosition"]);
      }
    }
    points = &order_points;
    if (document.contains("orderId") && document["orderId"].is_string()) {
      path.label = document["orderId"].get<std::string>();
    }
  } else if ((points = FindLineString(document)) != nullptr) {
    const json* properties = nullptr;
    if (document.value("type", "") == "FeatureCollection" && !document["features"].empty()) {
      properties = &document["features"][0]["properties"];
    }
    if (properties && properties->is_object() && properties->contains("job_id") &&
        (*properties)["job_id"].is_string()) {
      path.label = (*properties)["job_id"].get<std::string>();
    }
  } else {
    return absl::InvalidArgumentError(absl::StrCat(
        file,
        ": no path found (expected {\"path\": [...]}, an array of points, or a GeoJSON "
        "LineString)"));
  }
  absl::StatusOr<std::vector<v1::Point>> parsed = PointsFromJson(*points, file);
  if (!parsed.ok()) return parsed.status();
  path.points = *std::move(parsed);
  return path;
}

absl::StatusOr<PathFile> ParseCsvPath(const std::string& file, const std::string& text) {
  PathFile path;
  path.label = std::filesystem::path(file).stem().string();
  int line_number = 0;
  for (absl::string_view line : absl::StrSplit(text, '\n')) {
    ++line_number;
    line = absl::StripAsciiWhitespace(line);
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = absl::StrSplit(line, ',');
    double values[3] = {0, 0, 0};
    bool numeric = cells.size() >= 2 && cells.size() <= 3;
    for (size_t i = 0; numeric && i < cells.size(); ++i) {
      numeric = absl::SimpleAtod(std::string(absl::StripAsciiWhitespace(cells[i])), &values[i]);
    }
    if (!numeric) {
      if (path.points.empty() && line_number == 1) continue;  // the header
      return absl::InvalidArgumentError(
          absl::StrCat(file, ":", line_number, ": expected x,y or x,y,z"));
    }
    v1::Point point;
    point.set_x(values[0]);
    point.set_y(values[1]);
    point.set_z(values[2]);
    path.points.push_back(point);
  }
  return path;
}

}  // namespace

std::vector<std::string> PathFormats() { return {"json", "csv", "geojson", "vda5050"}; }

absl::StatusOr<std::string> PathFormatFor(const std::string& file, const std::string& format) {
  if (!format.empty()) return format;
  const std::string extension =
      absl::AsciiStrToLower(std::filesystem::path(file).extension().string());
  if (extension == ".json") return std::string("json");
  if (extension == ".csv") return std::string("csv");
  if (extension == ".geojson") return std::string("geojson");
  return absl::InvalidArgumentError(
      absl::StrCat("--output ", file,
                   ": cannot tell the format from the extension; use .json, .csv or "
                   ".geojson, or give --output-format"));
}

absl::Status WritePathFile(const std::string& file, const std::string& format, const v1::Job& job) {
  const v1::PlanResult& result = job.result();
  const auto& points = BestPath(result);
  if (points.empty()) {
    return absl::FailedPreconditionError(
        absl::StrCat("job ", job.id(), " has no path to write to ", file));
  }
  const bool with_z = HasZ(points) || HasZ(result.raw_path());
  std::string text;
  if (format == "vda5050") {
    absl::StatusOr<json> order = Vda5050Order(job, absl::Now());
    if (!order.ok()) return order.status();
    text = order->dump(2) + "\n";
  } else if (format == "csv") {
    text = with_z ? "x,y,z\n" : "x,y\n";
    for (const v1::Point& p : points) {
      text += with_z ? absl::StrCat(p.x(), ",", p.y(), ",", p.z(), "\n")
                     : absl::StrCat(p.x(), ",", p.y(), "\n");
    }
  } else {
    const v1::PathMetrics& metrics =
        result.smoothed_path().empty() ? result.raw_metrics() : result.smoothed_metrics();
    json properties = {{"job_id", job.id()},
                       {"algorithm", result.algorithm()},
                       {"state", JobStateName(job.state())},
                       {"map_id", job.request().map_id()},
                       {"seed", job.seed()},
                       {"smoothing", result.smoothing()},
                       {"length", metrics.length()},
                       {"collision_free", metrics.collision_free()}};
    json document;
    if (format == "geojson") {
      json feature = {
          {"type", "Feature"},
          {"properties", properties},
          {"geometry", {{"type", "LineString"}, {"coordinates", PointsToJson(points, with_z)}}}};
      document = {{"type", "FeatureCollection"}, {"features", json::array({feature})}};
    } else {
      document = properties;
      document["path"] = PointsToJson(points, with_z);
      document["raw_path"] = PointsToJson(result.raw_path(), with_z);
    }
    text = document.dump(2) + "\n";
  }
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) return absl::PermissionDeniedError(absl::StrCat("--output ", file, ": cannot write"));
  return absl::OkStatus();
}

absl::StatusOr<PathFile> ReadPathFile(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return absl::NotFoundError(absl::StrCat("--path ", file, ": cannot read"));
  std::ostringstream content;
  content << in.rdbuf();
  const std::string text = content.str();
  const std::string first(absl::StripLeadingAsciiWhitespace(text).substr(0, 1));
  if (first == "{" || first == "[") return ParseJsonPath(file, text);
  return ParseCsvPath(file, text);
}

}  // namespace swarmplan::client
