// Terrain from a CSV of heights or from a height image (PGM / PNG).

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "core/map/io/formats.h"
#include "core/map/io/image_decode.h"
#include "core/map/io/text_util.h"

namespace swarmplan {

absl::StatusOr<Terrain> ParseTerrainCsv(const MapFile& file, const LoadOptions& options) {
  using map_io_internal::InvalidAt;
  const std::string& name = file.name;
  if (auto s = map_io_internal::CheckFileSize(name, file.bytes.size(), options.limits); !s.ok()) {
    return s;
  }
  // First pass: count the rows and check each has as many fields as the first.
  int64_t width = 0;
  int64_t depth = 0;
  {
    map_io_internal::LineReader lines(file.bytes);
    std::string_view line;
    while (lines.Next(&line)) {
      if (map_io_internal::Trim(line).empty()) continue;
      const int64_t fields = static_cast<int64_t>(std::count(line.begin(), line.end(), ',')) + 1;
      if (depth == 0) width = fields;
      if (fields != width) {
        return InvalidAt(name, lines.line_number(),
                         absl::StrCat("row has ", fields, " values, the first row has ", width));
      }
      ++depth;
    }
  }
  if (depth == 0) return map_io_internal::Invalid(name, "no rows: the file is empty");
  if (auto s = map_io_internal::CheckCellCount(name, width, depth, options.limits); !s.ok()) {
    return s;
  }
  std::vector<double> heights(static_cast<size_t>(width * depth));
  map_io_internal::LineReader lines(file.bytes);
  std::string_view line;
  int64_t row = 0;
  while (lines.Next(&line)) {
    if (map_io_internal::Trim(line).empty()) continue;
    const auto fields = map_io_internal::Split(line, ',');
    const int64_t y = depth - 1 - row;  // the first line is the northernmost row
    for (int64_t x = 0; x < width; ++x) {
      const std::string_view field = map_io_internal::Trim(fields[x]);
      double value = 0.0;
      if (map_io_internal::Lower(field) == "nan") {
        value = std::numeric_limits<double>::quiet_NaN();
      } else if (!map_io_internal::ParseFiniteDouble(field, &value)) {
        return InvalidAt(name, lines.line_number(),
                         absl::StrCat("column ", x + 1, " is not a number (or nan): ",
                                      map_io_internal::Quote(field)));
      }
      heights[y * width + x] = value;
    }
    ++row;
  }
  auto terrain =
      Terrain::Create(static_cast<int>(width), static_cast<int>(depth), std::move(heights), 1.0,
                      Point2::Zero(), options.terrain_ceiling, options.limits);
  if (!terrain.ok()) return map_io_internal::WithFile(name, terrain.status());
  return terrain;
}

absl::StatusOr<Terrain> ParseTerrainImage(const MapFile& file, const LoadOptions& options) {
  const double scale = options.terrain_height_scale;
  if (!std::isfinite(scale) || scale <= 0) {
    return map_io_internal::Invalid(
        file.name, absl::StrCat("terrain_height_scale must be a positive number, got ", scale));
  }
  auto image = DecodeImage(file.name, file.bytes, options.limits);
  if (!image.ok()) return image.status();
  const int width = image->width;
  const int depth = image->height;
  std::vector<double> heights(static_cast<size_t>(width) * depth);
  for (int row = 0; row < depth; ++row) {
    const int y = depth - 1 - row;  // image row 0 is the north edge
    for (int x = 0; x < width; ++x) {
      heights[static_cast<size_t>(y) * width + x] =
          image->Grey(static_cast<size_t>(row) * width + x) * scale;
    }
  }
  auto terrain = Terrain::Create(width, depth, std::move(heights), 1.0, Point2::Zero(),
                                 options.terrain_ceiling, options.limits);
  if (!terrain.ok()) return map_io_internal::WithFile(file.name, terrain.status());
  return terrain;
}

}  // namespace swarmplan
