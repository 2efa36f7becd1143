// ROS map_server maps: a YAML file and the PGM or PNG image it names. Pixels become cells as
// map_server's image_loader does: grey = mean of the colour channels (0..255), negated when
// `negate`; p = (255 - grey) / 255; occupied (100) when p > occupied_thresh, free (0) when
// p < free_thresh, otherwise unknown (-1) in trinary mode, 99 * (p - free) / (occ - free) in
// scale mode (unknown there too for a fully transparent pixel); raw mode keeps the grey level
// itself (0..100, and 255 as unknown). Image row 0 is the top of the map: y = height - 1 - row.

#include <cmath>
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "core/map/io/formats.h"
#include "core/map/io/image_decode.h"
#include "core/map/io/text_util.h"
#include "yaml-cpp/yaml.h"

namespace swarmplan {
namespace {

enum class Mode { kTrinary, kScale, kRaw };

struct RosMapInfo {
  double resolution = 1.0;
  Point2 origin = Point2::Zero();
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  Mode mode = Mode::kTrinary;
};

absl::Status FieldError(const std::string& field, const std::string& message) {
  return absl::InvalidArgumentError(absl::StrCat(field, ": ", message));
}

absl::StatusOr<double> ReadNumber(const YAML::Node& node, const std::string& field) {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    return FieldError(field, "must be a number");
  }
  return value;
}

absl::StatusOr<RosMapInfo> ReadInfo(const YAML::Node& root) {
  if (!root.IsMap()) {
    return absl::InvalidArgumentError("the YAML must be a mapping with image, resolution, origin");
  }
  RosMapInfo info;
  if (!root["resolution"]) return FieldError("resolution", "missing");
  auto resolution = ReadNumber(root["resolution"], "resolution");
  if (!resolution.ok()) return resolution.status();
  if (*resolution <= 0) return FieldError("resolution", "must be positive");
  info.resolution = *resolution;

  const YAML::Node origin = root["origin"];
  if (!origin) return FieldError("origin", "missing ([x, y, yaw])");
  if (!origin.IsSequence() || origin.size() != 3)
    return FieldError("origin", "must be [x, y, yaw]");
  for (int i = 0; i < 3; ++i) {
    auto v = ReadNumber(origin[i], absl::StrCat("origin[", i, "]"));
    if (!v.ok()) return v.status();
    if (i < 2) info.origin[i] = *v;
    if (i == 2 && *v != 0.0) {
      return FieldError("origin[2]", "a rotated map (yaw != 0) is not supported");
    }
  }

  if (const YAML::Node negate = root["negate"]) {
    int as_int = 0;
    bool as_bool = false;
    if (negate.IsScalar() && YAML::convert<int>::decode(negate, as_int) &&
        (as_int == 0 || as_int == 1)) {
      info.negate = as_int == 1;
    } else if (negate.IsScalar() && YAML::convert<bool>::decode(negate, as_bool)) {
      info.negate = as_bool;
    } else {
      return FieldError("negate", "must be 0, 1, true or false");
    }
  }
  for (auto [key, out] : {std::pair{"occupied_thresh", &info.occupied_thresh},
                          std::pair{"free_thresh", &info.free_thresh}}) {
    if (!root[key]) continue;
    auto v = ReadNumber(root[key], key);
    if (!v.ok()) return v.status();
    if (*v < 0 || *v > 1) return FieldError(key, "must be in [0, 1]");
    *out = *v;
  }
  if (!(info.free_thresh < info.occupied_thresh)) {
    return FieldError("free_thresh",
                      absl::StrCat("must be below occupied_thresh (", info.occupied_thresh, ")"));
  }
  if (const YAML::Node mode = root["mode"]) {
    const std::string m = mode.IsScalar() ? mode.Scalar() : "";
    if (m == "trinary") {
      info.mode = Mode::kTrinary;
    } else if (m == "scale") {
      info.mode = Mode::kScale;
    } else if (m == "raw") {
      info.mode = Mode::kRaw;
    } else {
      return FieldError("mode", absl::StrCat("must be trinary, scale or raw, got \"", m, "\""));
    }
  }
  return info;
}

// The image the YAML names and the image file given with it must have the same base name.
absl::Status CheckImageName(const std::string& named, const std::string& given) {
  const std::string named_base = std::filesystem::path(named).filename().string();
  const std::string given_base = std::filesystem::path(given).filename().string();
  if (named_base.empty() || named_base != given_base) {
    return FieldError(
        "image",
        absl::StrCat("names ", map_io_internal::Quote(named), " but the image file given is ",
                     map_io_internal::Quote(given), " (their base names must match)"));
  }
  return absl::OkStatus();
}

absl::StatusOr<OccupancyGrid> ImageToGrid(const std::string& file, const DecodedImage& image,
                                          const RosMapInfo& info, const MapLimits& limits) {
  const int width = image.width;
  const int height = image.height;
  std::vector<int8_t> cells(static_cast<size_t>(width) * height);
  for (int row = 0; row < height; ++row) {
    for (int x = 0; x < width; ++x) {
      const size_t pixel = static_cast<size_t>(row) * width + x;
      double grey = image.Grey255(pixel);
      if (info.negate) grey = 255.0 - grey;
      int8_t value = 0;
      if (info.mode == Mode::kRaw) {
        const int raw = static_cast<int>(grey);  // map_server truncates to a byte
        if (raw == 255) {
          value = OccupancyGrid::kUnknown;
        } else if (raw <= 100) {
          value = static_cast<int8_t>(raw);
        } else {
          return map_io_internal::Invalid(
              file, absl::StrCat("pixel ", x, ",", row, " (column, row) has value ", raw,
                                 "; raw mode allows 0..100 and 255 (unknown)"));
        }
      } else {
        const double p = (255.0 - grey) / 255.0;
        const bool transparent =
            image.HasAlpha() && image.alpha[pixel] * 255.0 / image.max_value < 1.0;
        if (p > info.occupied_thresh) {
          value = OccupancyGrid::kOccupied;
        } else if (p < info.free_thresh) {
          value = OccupancyGrid::kFree;
        } else if (info.mode == Mode::kTrinary || transparent) {
          value = OccupancyGrid::kUnknown;
        } else {
          const double ratio = (p - info.free_thresh) / (info.occupied_thresh - info.free_thresh);
          value = static_cast<int8_t>(99.0 * ratio);
        }
      }
      cells[static_cast<size_t>(height - 1 - row) * width + x] = value;
    }
  }
  auto grid =
      OccupancyGrid::Create(width, height, std::move(cells), info.resolution, info.origin, limits);
  if (!grid.ok()) return map_io_internal::WithFile(file, grid.status());
  return grid;
}

absl::Status CheckYamlSize(const MapFile& yaml) {
  if (yaml.bytes.size() <= kMaxRosYamlBytes) return absl::OkStatus();
  return absl::ResourceExhaustedError(absl::StrCat(yaml.name, ": ", yaml.bytes.size(),
                                                   " bytes exceed the limit of ", kMaxRosYamlBytes,
                                                   " bytes for a ROS map YAML"));
}

}  // namespace

absl::StatusOr<std::string> RosMapImagePath(const MapFile& yaml) {
  if (absl::Status s = CheckYamlSize(yaml); !s.ok()) return s;
  try {
    const YAML::Node root = YAML::Load(yaml.bytes);
    if (!root.IsMap() || !root["image"] || !root["image"].IsScalar()) {
      return map_io_internal::Invalid(yaml.name, "image: missing (the image file name)");
    }
    const std::filesystem::path image(root["image"].Scalar());
    if (image.empty()) return map_io_internal::Invalid(yaml.name, "image: empty");
    if (image.is_absolute()) return image.string();
    return (std::filesystem::path(yaml.name).parent_path() / image).string();
  } catch (const YAML::Exception& e) {
    return map_io_internal::Invalid(yaml.name, absl::StrCat("not valid YAML: ", e.what()));
  }
}

absl::StatusOr<OccupancyGrid> ParseRosMap(const MapFile& yaml, const MapFile& image,
                                          const MapLimits& limits) {
  if (auto s = map_io_internal::CheckFileSize(yaml.name, yaml.bytes.size(), limits); !s.ok()) {
    return s;
  }
  if (absl::Status s = CheckYamlSize(yaml); !s.ok()) return s;
  absl::StatusOr<RosMapInfo> info;
  try {
    const YAML::Node root = YAML::Load(yaml.bytes);
    if (root.IsMap() && (!root["image"] || !root["image"].IsScalar())) {
      return map_io_internal::Invalid(yaml.name, "image: missing (the image file name)");
    }
    info = ReadInfo(root);
    if (info.ok()) {
      if (auto s = CheckImageName(root["image"].Scalar(), image.name); !s.ok()) info = s;
    }
  } catch (const YAML::Exception& e) {
    return map_io_internal::Invalid(yaml.name, absl::StrCat("not valid YAML: ", e.what()));
  }
  if (!info.ok()) return map_io_internal::WithFile(yaml.name, info.status());
  auto decoded = DecodeImage(image.name, image.bytes, limits);
  if (!decoded.ok()) return decoded.status();
  return ImageToGrid(image.name, *decoded, *info, limits);
}

absl::StatusOr<OccupancyGrid> ParseOccupancyImage(const MapFile& image, const MapLimits& limits) {
  auto decoded = DecodeImage(image.name, image.bytes, limits);
  if (!decoded.ok()) return decoded.status();
  return ImageToGrid(image.name, *decoded, RosMapInfo{}, limits);
}

}  // namespace swarmplan
