// ESRI ASCII grids (.asc) as Terrain.

#include <cmath>
#include <map>

#include "absl/strings/str_cat.h"
#include "core/map/io/formats.h"
#include "core/map/io/text_util.h"

namespace swarmplan {
namespace {

using map_io_internal::InvalidAt;
using map_io_internal::ParseFiniteDouble;
using map_io_internal::Quote;

constexpr const char* kHeaderKeys[] = {"ncols",     "nrows",     "xllcorner", "xllcenter",
                                       "yllcorner", "yllcenter", "cellsize",  "nodata_value"};

bool IsHeaderKey(const std::string& key) {
  for (const char* k : kHeaderKeys) {
    if (key == k) return true;
  }
  return false;
}

}  // namespace

absl::StatusOr<Terrain> ParseTerrainAsc(const MapFile& file, const LoadOptions& options) {
  const std::string& name = file.name;
  if (auto s = map_io_internal::CheckFileSize(name, file.bytes.size(), options.limits); !s.ok()) {
    return s;
  }
  map_io_internal::LineReader lines(file.bytes);
  std::string_view line;
  std::map<std::string, double> header;
  // Header: "key value" lines until the first line that starts with a number.
  bool have_data_line = false;
  while (lines.Next(&line)) {
    const auto words = map_io_internal::SplitWhitespace(line);
    if (words.empty()) continue;
    double first = 0.0;
    if (ParseFiniteDouble(words[0], &first)) {
      have_data_line = true;
      break;
    }
    const std::string key = map_io_internal::Lower(words[0]);
    if (!IsHeaderKey(key)) {
      return InvalidAt(name, lines.line_number(),
                       absl::StrCat("unknown header key ", Quote(words[0]),
                                    " (expected ncols, nrows, xllcorner|xllcenter, "
                                    "yllcorner|yllcenter, cellsize, NODATA_value)"));
    }
    double value = 0.0;
    if (words.size() != 2 || !ParseFiniteDouble(words[1], &value)) {
      return InvalidAt(
          name, lines.line_number(),
          absl::StrCat("expected '", std::string(words[0]), " NUMBER', got ", Quote(line)));
    }
    if (!header.emplace(key, value).second) {
      return InvalidAt(name, lines.line_number(),
                       absl::StrCat("header key ", std::string(words[0]), " given twice"));
    }
  }
  const int header_end = have_data_line ? lines.line_number() : lines.line_number() + 1;
  for (const char* key : {"ncols", "nrows", "cellsize"}) {
    if (!header.count(key)) {
      return InvalidAt(name, header_end, absl::StrCat("the header lacks '", key, "'"));
    }
  }
  for (const char* axis : {"x", "y"}) {
    const bool corner = header.count(absl::StrCat(axis, "llcorner")) > 0;
    const bool center = header.count(absl::StrCat(axis, "llcenter")) > 0;
    if (corner == center) {
      return InvalidAt(name, header_end,
                       absl::StrCat("the header needs exactly one of '", axis, "llcorner' and '",
                                    axis, "llcenter'"));
    }
  }
  const double ncols = header["ncols"];
  const double nrows = header["nrows"];
  for (const auto& [key, value] : {std::pair{"ncols", ncols}, std::pair{"nrows", nrows}}) {
    if (value != std::floor(value) || value < 1 || value > (1 << 30)) {
      return map_io_internal::Invalid(
          name, absl::StrCat("header ", key, " must be a positive integer, got ", value));
    }
  }
  const double cell_size = header["cellsize"];
  if (cell_size <= 0) {
    return map_io_internal::Invalid(
        name, absl::StrCat("header cellsize must be positive, got ", cell_size));
  }
  const int width = static_cast<int>(ncols);
  const int depth = static_cast<int>(nrows);
  if (auto s = map_io_internal::CheckCellCount(name, width, depth, options.limits); !s.ok()) {
    return s;
  }
  // Each value takes at least two bytes (a digit and a separator): check before allocating.
  if (static_cast<int64_t>(width) * depth > static_cast<int64_t>(file.bytes.size()) / 2 + 1) {
    return map_io_internal::Invalid(
        name, absl::StrCat("the header declares ", width, " x ", depth,
                           " values, more than the file's ", file.bytes.size(), " bytes can hold"));
  }
  Point2 origin;
  origin.x() =
      header.count("xllcorner") ? header["xllcorner"] : header["xllcenter"] - cell_size / 2;
  origin.y() =
      header.count("yllcorner") ? header["yllcorner"] : header["yllcenter"] - cell_size / 2;
  const bool has_nodata = header.count("nodata_value") > 0;
  const double nodata = has_nodata ? header["nodata_value"] : 0.0;

  std::vector<double> heights(static_cast<size_t>(width) * depth);
  int row = 0;
  bool pending = have_data_line;  // `line` already holds the first data line
  while (pending || lines.Next(&line)) {
    pending = false;
    const auto words = map_io_internal::SplitWhitespace(line);
    if (words.empty()) continue;
    if (row == depth) {
      return InvalidAt(name, lines.line_number(),
                       absl::StrCat("more than the ", depth, " data rows nrows declares"));
    }
    if (static_cast<int>(words.size()) != width) {
      return InvalidAt(
          name, lines.line_number(),
          absl::StrCat("data row ", row + 1, " has ", words.size(), " values, ncols says ", width));
    }
    const int y = depth - 1 - row;  // the first data row is the northernmost
    for (int x = 0; x < width; ++x) {
      double value = 0.0;
      if (!ParseFiniteDouble(words[x], &value)) {
        return InvalidAt(name, lines.line_number(),
                         absl::StrCat("value ", x + 1, " is not a number: ", Quote(words[x])));
      }
      if (has_nodata && value == nodata) value = std::numeric_limits<double>::quiet_NaN();
      heights[static_cast<size_t>(y) * width + x] = value;
    }
    ++row;
  }
  if (row != depth) {
    return InvalidAt(
        name, lines.line_number() + 1,
        absl::StrCat("the file ends after ", row, " of the ", depth, " data rows nrows declares"));
  }
  auto terrain = Terrain::Create(width, depth, std::move(heights), cell_size, origin,
                                 options.terrain_ceiling, options.limits);
  if (!terrain.ok()) return map_io_internal::WithFile(name, terrain.status());
  return terrain;
}

}  // namespace swarmplan
