#pragma once

// The work bound of PNG decoding: before libpng inflates the image data, the IDAT chunks are
// inflated here into a scratch buffer that stops one byte past what the declared size needs.
// A small file whose data inflates far beyond its declared size (a decompression bomb) is
// refused after that many bytes, whatever its inflated size. Internal to core/map/io.

#include <cstdint>
#include <string>

#include "absl/status/status.h"

namespace swarmplan::map_io_internal {

// The image header fields that fix the size of the inflated image data.
struct PngLayout {
  uint32_t width = 0;
  uint32_t height = 0;
  int bit_depth = 8;
  int channels = 1;  // samples per pixel in the file: 1 grey/palette, 2, 3 RGB, 4 RGBA
  bool interlaced = false;
};

// How much work the check did, for tests of its bound.
struct PngDecodeStats {
  int64_t inflated_bytes = 0;    // bytes of image data produced by inflating
  int64_t compressed_bytes = 0;  // IDAT bytes the inflater consumed
};

// The bytes the inflated image data of `layout` holds: per row of each (Adam7) pass, one filter
// byte and the packed samples.
int64_t PngImageDataSize(const PngLayout& layout);

// `png` is a whole PNG file whose header has been read. OK when its IDAT chunks are consecutive
// and hold one zlib stream that inflates to exactly PngImageDataSize(layout) bytes and ends
// with the last IDAT; otherwise INVALID_ARGUMENT with the problem (no file name).
absl::Status CheckPngImageData(const std::string& png, const PngLayout& layout,
                               PngDecodeStats* stats = nullptr);

}  // namespace swarmplan::map_io_internal
