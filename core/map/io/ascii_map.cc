// ASCII art grids: '.' free, '#' or '@' blocked, first line y = 0.

#include <string_view>

#include "absl/strings/str_cat.h"
#include "core/map/io/formats.h"
#include "core/map/io/text_util.h"

namespace swarmplan {

absl::StatusOr<OccupancyGrid> ParseAsciiMap(const MapFile& file, const MapLimits& limits) {
  using map_io_internal::InvalidAt;
  const std::string& name = file.name;
  if (auto s = map_io_internal::CheckFileSize(name, file.bytes.size(), limits); !s.ok()) return s;
  // First pass: the rows (blank lines after the last row are ignored) and their width.
  std::vector<std::string_view> rows;
  int first_blank = 0;  // line number of a blank line seen after a row, 0 if none
  map_io_internal::LineReader lines(file.bytes);
  std::string_view line;
  while (lines.Next(&line)) {
    if (line.empty()) {
      if (first_blank == 0) first_blank = lines.line_number();
      continue;
    }
    if (first_blank != 0) {
      return InvalidAt(name, first_blank, "blank line inside the map");
    }
    if (!rows.empty() && line.size() != rows.front().size()) {
      return InvalidAt(name, lines.line_number(),
                       absl::StrCat("row has ", line.size(), " characters, expected ",
                                    rows.front().size(), " like line 1"));
    }
    for (size_t x = 0; x < line.size(); ++x) {
      const char c = line[x];
      if (c != '.' && c != '#' && c != '@') {
        return InvalidAt(name, lines.line_number(),
                         absl::StrCat("column ", x + 1, ": ",
                                      map_io_internal::Quote(std::string_view(&line[x], 1)),
                                      " is not '.' (free), '#' or '@' (blocked)"));
      }
    }
    rows.push_back(line);
  }
  if (rows.empty()) return map_io_internal::Invalid(name, "no rows: the map is empty");
  const int64_t width = static_cast<int64_t>(rows.front().size());
  const int64_t height = static_cast<int64_t>(rows.size());
  if (auto s = map_io_internal::CheckCellCount(name, width, height, limits); !s.ok()) return s;
  std::vector<int8_t> cells(static_cast<size_t>(width * height));
  for (int64_t y = 0; y < height; ++y) {
    for (int64_t x = 0; x < width; ++x) {
      cells[y * width + x] = rows[y][x] == '.' ? OccupancyGrid::kFree : OccupancyGrid::kOccupied;
    }
  }
  auto grid = OccupancyGrid::Create(static_cast<int>(width), static_cast<int>(height),
                                    std::move(cells), 1.0, Point2::Zero(), limits);
  if (!grid.ok()) return map_io_internal::WithFile(name, grid.status());
  return grid;
}

}  // namespace swarmplan
