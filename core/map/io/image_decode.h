#pragma once

// Decoding of PGM (P2 plain, P5 binary) and PNG images for the occupancy and height loaders.
// Internal to core/map/io.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/io/png_image_data.h"
#include "core/map/limits.h"

namespace swarmplan {

// Pixels in file order (row 0 is the top row), kept at the image's own depth.
struct DecodedImage {
  int width = 0;
  int height = 0;
  int colour_channels = 1;  // 1 (grey) or 3 (RGB); alpha is kept apart
  int max_value = 255;      // the largest sample: 255, 65535 (16-bit PNG) or a PGM's maxval
  std::vector<uint32_t> channel_sum;  // per pixel, the sum of its colour channels
  std::vector<uint16_t> alpha;        // per pixel (0..max_value); empty without alpha

  // The mean of the colour channels, in 0..max_value.
  double Grey(size_t pixel) const {
    return static_cast<double>(channel_sum[pixel]) / colour_channels;
  }
  // The same on map_server's 0..255 scale.
  double Grey255(size_t pixel) const { return Grey(pixel) * 255.0 / max_value; }
  bool HasAlpha() const { return !alpha.empty(); }
};

// PNG (by its signature) or PGM ("P2" / "P5"). PNG palettes and grey levels below 8 bits are
// expanded, a tRNS chunk becomes alpha. The limits are checked before pixels are allocated.
// Errors name the file and, for PGM, the line or pixel.
absl::StatusOr<DecodedImage> DecodeImage(const std::string& file, const std::string& bytes,
                                         const MapLimits& limits);
absl::StatusOr<DecodedImage> DecodePgm(const std::string& file, const std::string& bytes,
                                       const MapLimits& limits);
// Inflates at most one byte more image data than the declared size needs (see
// png_image_data.h); `stats`, when given, counts that work.
absl::StatusOr<DecodedImage> DecodePng(const std::string& file, const std::string& bytes,
                                       const MapLimits& limits,
                                       map_io_internal::PngDecodeStats* stats = nullptr);

}  // namespace swarmplan
