// Moving AI Lab grid benchmarks: the .map grid and the .scen scenario list.

#include <filesystem>
#include <string_view>

#include "absl/strings/str_cat.h"
#include "core/map/io/formats.h"
#include "core/map/io/map_io.h"
#include "core/map/io/text_util.h"

namespace swarmplan {
namespace {

using map_io_internal::CheckCellCount;
using map_io_internal::CheckFileSize;
using map_io_internal::InvalidAt;
using map_io_internal::LineReader;
using map_io_internal::ParseFiniteDouble;
using map_io_internal::ParseInt;
using map_io_internal::Quote;
using map_io_internal::SplitWhitespace;
using map_io_internal::Trim;

bool IsPassable(char c) { return c == '.' || c == 'G' || c == 'S'; }

// Reads "key value" with a positive integer value.
absl::Status ReadDimension(const std::string& file, LineReader& lines, const std::string& key,
                           int* out) {
  std::string_view line;
  if (!lines.Next(&line)) {
    return InvalidAt(file, lines.line_number() + 1, absl::StrCat("missing '", key, " N' line"));
  }
  const auto words = SplitWhitespace(line);
  int64_t value = 0;
  if (words.size() != 2 || words[0] != key || !ParseInt(words[1], &value) || value <= 0 ||
      value > (1 << 30)) {
    return InvalidAt(
        file, lines.line_number(),
        absl::StrCat("expected '", key, " N' with N a positive integer, got ", Quote(line)));
  }
  *out = static_cast<int>(value);
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<OccupancyGrid> ParseMovingAiMap(const MapFile& file, const MapLimits& limits) {
  const std::string& name = file.name;
  if (auto s = CheckFileSize(name, file.bytes.size(), limits); !s.ok()) return s;
  LineReader lines(file.bytes);
  std::string_view line;
  if (!lines.Next(&line) ||
      SplitWhitespace(line) != std::vector<std::string_view>{"type", "octile"}) {
    return InvalidAt(name, 1, absl::StrCat("expected 'type octile', got ", Quote(line)));
  }
  int height = 0;
  int width = 0;
  if (auto s = ReadDimension(name, lines, "height", &height); !s.ok()) return s;
  if (auto s = ReadDimension(name, lines, "width", &width); !s.ok()) return s;
  if (!lines.Next(&line) || Trim(line) != "map") {
    return InvalidAt(name, 4, absl::StrCat("expected 'map', got ", Quote(line)));
  }
  if (auto s = CheckCellCount(name, width, height, limits); !s.ok()) return s;
  // The header could claim more cells than the file holds: check before allocating.
  if (static_cast<int64_t>(file.bytes.size()) < static_cast<int64_t>(width) * height) {
    return InvalidAt(name, 2,
                     absl::StrCat("header says ", width, " x ", height, " cells but the file has ",
                                  file.bytes.size(), " bytes"));
  }
  std::vector<int8_t> cells(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    if (!lines.Next(&line)) {
      return InvalidAt(name, lines.line_number() + 1,
                       absl::StrCat("the file ends after ", y, " of ", height, " rows"));
    }
    if (static_cast<int64_t>(line.size()) != width) {
      return InvalidAt(
          name, lines.line_number(),
          absl::StrCat("row ", y, " has ", line.size(), " characters, expected ", width));
    }
    for (int x = 0; x < width; ++x) {
      cells[static_cast<size_t>(y) * width + x] =
          IsPassable(line[x]) ? OccupancyGrid::kFree : OccupancyGrid::kOccupied;
    }
  }
  while (lines.Next(&line)) {
    if (!Trim(line).empty()) {
      return InvalidAt(name, lines.line_number(),
                       absl::StrCat("more than the ", height, " rows the header declares"));
    }
  }
  auto grid = OccupancyGrid::Create(width, height, std::move(cells), 1.0, Point2::Zero(), limits);
  if (!grid.ok()) return map_io_internal::WithFile(name, grid.status());
  return grid;
}

absl::StatusOr<std::vector<Scenario>> ParseScenarios(const std::string& name,
                                                     const std::string& bytes) {
  LineReader lines(bytes);
  std::string_view line;
  if (!lines.Next(&line) || (Trim(line) != "version 1" && Trim(line) != "version 1.0")) {
    return InvalidAt(name, 1, absl::StrCat("expected 'version 1', got ", Quote(line)));
  }
  std::vector<Scenario> scenarios;
  while (lines.Next(&line)) {
    if (Trim(line).empty()) continue;
    const int n = lines.line_number();
    const auto fields = map_io_internal::Split(line, '\t');
    if (fields.size() != 9) {
      return InvalidAt(name, n,
                       absl::StrCat("expected 9 tab-separated fields, got ", fields.size()));
    }
    static const char* const kNames[] = {"bucket",  "map",     "width",  "height",
                                         "start_x", "start_y", "goal_x", "goal_y"};
    int64_t ints[8] = {};
    for (int i = 0; i < 8; ++i) {
      if (i == 1) continue;
      if (!ParseInt(Trim(fields[i]), &ints[i]) || ints[i] < 0 || ints[i] > (1 << 30)) {
        return InvalidAt(name, n,
                         absl::StrCat("field ", i + 1, " (", kNames[i],
                                      ") must be a non-negative integer, got ", Quote(fields[i])));
      }
    }
    Scenario s;
    s.bucket = static_cast<int>(ints[0]);
    s.map_name = std::filesystem::path(std::string(Trim(fields[1]))).filename().string();
    s.width = static_cast<int>(ints[2]);
    s.height = static_cast<int>(ints[3]);
    s.start = Cell{static_cast<int>(ints[4]), static_cast<int>(ints[5])};
    s.goal = Cell{static_cast<int>(ints[6]), static_cast<int>(ints[7])};
    if (s.map_name.empty()) return InvalidAt(name, n, "field 2 (map) is empty");
    if (!ParseFiniteDouble(Trim(fields[8]), &s.optimal_length) || s.optimal_length < 0) {
      return InvalidAt(name, n,
                       absl::StrCat("field 9 (optimal_length) must be a non-negative number, got ",
                                    Quote(fields[8])));
    }
    for (const auto& [cell, what] : {std::pair{s.start, "start"}, std::pair{s.goal, "goal"}}) {
      if (cell.x >= s.width || cell.y >= s.height) {
        return InvalidAt(name, n,
                         absl::StrCat(what, " ", cell.x, ",", cell.y, " lies outside the ", s.width,
                                      " x ", s.height, " map"));
      }
    }
    scenarios.push_back(std::move(s));
  }
  return scenarios;
}

}  // namespace swarmplan
