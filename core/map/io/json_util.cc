#include "core/map/io/json_util.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "core/geometry/simple_polygon.h"

namespace swarmplan::map_io_internal {

absl::StatusOr<nlohmann::json> ParseJson(const std::string& file, const std::string& bytes) {
  try {
    return nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::exception& e) {
    return absl::InvalidArgumentError(absl::StrCat(file, ": not valid JSON: ", e.what()));
  }
}

absl::StatusOr<double> JsonNumber(const nlohmann::json& value, const std::string& path) {
  if (!value.is_number())
    return absl::InvalidArgumentError(absl::StrCat(path, ": must be a number"));
  const double v = value.get<double>();
  if (!std::isfinite(v)) return absl::InvalidArgumentError(absl::StrCat(path, ": must be finite"));
  return v;
}

absl::StatusOr<Point2> JsonPoint(const nlohmann::json& value, const std::string& path) {
  if (!value.is_array() || value.size() < 2 || value.size() > 3) {
    return absl::InvalidArgumentError(absl::StrCat(path, ": must be a point [x, y]"));
  }
  Point2 p;
  for (int i = 0; i < 2; ++i) {
    auto v = JsonNumber(value[i], absl::StrCat(path, "[", i, "]"));
    if (!v.ok()) return v.status();
    p[i] = *v;
  }
  return p;
}

absl::StatusOr<std::pair<Point2, Point2>> JsonBounds(const nlohmann::json& value,
                                                     const std::string& path) {
  if (!value.is_array() || value.size() != 4) {
    return absl::InvalidArgumentError(absl::StrCat(path, ": must be [xmin, ymin, xmax, ymax]"));
  }
  double v[4];
  for (int i = 0; i < 4; ++i) {
    auto n = JsonNumber(value[i], absl::StrCat(path, "[", i, "]"));
    if (!n.ok()) return n.status();
    v[i] = *n;
  }
  if (!(v[2] > v[0] && v[3] > v[1])) {
    return absl::InvalidArgumentError(
        absl::StrCat(path, ": [xmin, ymin, xmax, ymax] needs xmax > xmin and ymax > ymin"));
  }
  return std::pair{Point2(v[0], v[1]), Point2(v[2], v[3])};
}

absl::Status CleanRing(std::vector<Point2>* ring, const std::string& path) {
  std::vector<Point2> out;
  out.reserve(ring->size());
  for (const Point2& p : *ring) {
    if (out.empty() || out.back() != p) out.push_back(p);
  }
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  if (out.size() < 3) {
    return absl::InvalidArgumentError(
        absl::StrCat(path, ": a polygon needs at least 3 distinct vertices, got ", out.size()));
  }
  double area = 0.0;
  for (size_t i = 0; i < out.size(); ++i) {
    const Point2& a = out[i];
    const Point2& b = out[(i + 1) % out.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  if (area == 0.0) {
    return absl::InvalidArgumentError(absl::StrCat(path, ": polygon has zero area"));
  }
  if (absl::Status s = CheckSimplePolygon(out); !s.ok()) {
    return absl::Status(s.code(), absl::StrCat(path, ": ", s.message()));
  }
  *ring = std::move(out);
  return absl::OkStatus();
}

}  // namespace swarmplan::map_io_internal
