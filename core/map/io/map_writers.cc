#include "core/map/io/map_writers.h"

#include <charconv>
#include <system_error>

#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"

namespace swarmplan {
namespace {

// Shortest decimal text that reads back to exactly `value`.
std::string ShortestNumber(double value) {
  char buffer[32];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (result.ec != std::errc()) return "nan";  // 32 characters always suffice for a double
  return std::string(buffer, result.ptr);
}

std::string PointText(const Point2& p) {
  return absl::StrCat("[", ShortestNumber(p.x()), ", ", ShortestNumber(p.y()), "]");
}

}  // namespace

std::string FormatAsciiMap(const OccupancyGrid& grid) {
  std::string text;
  text.reserve(static_cast<size_t>(grid.width() + 1) * grid.height());
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) text += grid.IsBlocked(x, y) ? '#' : '.';
    text += '\n';
  }
  return text;
}

std::string FormatShapesJson(const ShapeWorld& world, const std::string& name) {
  const Bounds2& b = world.bounds();
  std::string out =
      absl::StrCat("{\n  \"name\": ", nlohmann::json(name).dump(), ",\n  \"bounds\": [",
                   ShortestNumber(b.min.x()), ", ", ShortestNumber(b.min.y()), ", ",
                   ShortestNumber(b.max.x()), ", ", ShortestNumber(b.max.y()), "]");
  if (!world.circles().empty()) {
    absl::StrAppend(&out, ",\n  \"circles\": [");
    for (size_t i = 0; i < world.circles().size(); ++i) {
      const Circle& c = world.circles()[i];
      absl::StrAppend(&out, i == 0 ? "\n    " : ",\n    ", "{\"center\": ", PointText(c.center),
                      ", \"radius\": ", ShortestNumber(c.radius), "}");
    }
    absl::StrAppend(&out, "\n  ]");
  }
  if (!world.polygons().empty()) {
    absl::StrAppend(&out, ",\n  \"polygons\": [");
    for (size_t i = 0; i < world.polygons().size(); ++i) {
      absl::StrAppend(&out, i == 0 ? "\n    [" : ",\n    [");
      const std::vector<Point2>& vertices = world.polygons()[i].vertices;
      for (size_t k = 0; k < vertices.size(); ++k) {
        absl::StrAppend(&out, k == 0 ? "" : ", ", PointText(vertices[k]));
      }
      absl::StrAppend(&out, "]");
    }
    absl::StrAppend(&out, "\n  ]");
  }
  absl::StrAppend(&out, "\n}\n");
  return out;
}

}  // namespace swarmplan
