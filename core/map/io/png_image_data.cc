#include "core/map/io/png_image_data.h"

#include <zlib.h>

#include <array>
#include <cstring>

#include "absl/strings/str_cat.h"

namespace swarmplan::map_io_internal {
namespace {

constexpr size_t kSignatureBytes = 8;
constexpr size_t kChunkOverhead = 12;  // length, type, CRC

uint32_t ReadBigEndian32(const unsigned char* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
}

int64_t RowBytes(int64_t pixels, const PngLayout& layout) {
  return (pixels * layout.channels * layout.bit_depth + 7) / 8;
}

// Inflates the IDAT payloads fed to it, never producing more than `limit` + 1 bytes in all.
class BoundedInflater {
 public:
  explicit BoundedInflater(int64_t limit) : limit_(limit) {
    std::memset(&stream_, 0, sizeof(stream_));
    ready_ = inflateInit(&stream_) == Z_OK;
  }
  ~BoundedInflater() {
    if (ready_) inflateEnd(&stream_);
  }
  BoundedInflater(const BoundedInflater&) = delete;
  BoundedInflater& operator=(const BoundedInflater&) = delete;

  // Inflates one IDAT payload.
  absl::Status Feed(const unsigned char* data, uint32_t size, PngDecodeStats* stats) {
    if (!ready_) return absl::InternalError("cannot start the inflater");
    if (ended_) {
      return absl::InvalidArgumentError(
          "extra image data after the end of the compressed stream (an IDAT chunk more than the "
          "image needs)");
    }
    stream_.next_in = const_cast<unsigned char*>(data);
    stream_.avail_in = size;
    while (stream_.avail_in > 0) {
      const int64_t room = limit_ + 1 - produced_;
      stream_.next_out = scratch_.data();
      stream_.avail_out = static_cast<uInt>(std::min<int64_t>(room, scratch_.size()));
      const uInt before = stream_.avail_in;
      const int status = inflate(&stream_, Z_NO_FLUSH);
      const int64_t out = static_cast<int64_t>(stream_.next_out - scratch_.data());
      produced_ += out;
      stats->inflated_bytes += out;
      stats->compressed_bytes += before - stream_.avail_in;
      if (produced_ > limit_) {
        return absl::InvalidArgumentError(absl::StrCat("the image data inflates to more than the ",
                                                       limit_, " bytes the declared size needs"));
      }
      if (status == Z_STREAM_END) {
        ended_ = true;
        if (stream_.avail_in > 0) {
          return absl::InvalidArgumentError(
              absl::StrCat("extra image data after the end of the compressed stream (",
                           stream_.avail_in, " bytes)"));
        }
        break;
      }
      if (status != Z_OK) {
        return absl::InvalidArgumentError(absl::StrCat(
            "corrupt image data: ", stream_.msg != nullptr ? stream_.msg : "inflate failed"));
      }
    }
    return absl::OkStatus();
  }

  // After the last IDAT chunk.
  absl::Status Finish() const {
    if (produced_ < limit_) {
      return absl::InvalidArgumentError(absl::StrCat("not enough image data: ", produced_,
                                                     " of the ", limit_,
                                                     " bytes the declared size needs"));
    }
    if (!ended_) {
      return absl::InvalidArgumentError(
          "the compressed image data is truncated (its stream does not end)");
    }
    return absl::OkStatus();
  }

 private:
  const int64_t limit_;
  z_stream stream_;
  bool ready_ = false;
  bool ended_ = false;
  int64_t produced_ = 0;
  std::array<unsigned char, 16384> scratch_;
};

}  // namespace

int64_t PngImageDataSize(const PngLayout& layout) {
  const int64_t width = layout.width;
  const int64_t height = layout.height;
  if (!layout.interlaced) return height * (1 + RowBytes(width, layout));
  // Adam7: the first column and row of each pass, and its steps.
  static constexpr int kX0[7] = {0, 4, 0, 2, 0, 1, 0};
  static constexpr int kDx[7] = {8, 8, 4, 4, 2, 2, 1};
  static constexpr int kY0[7] = {0, 0, 4, 0, 2, 0, 1};
  static constexpr int kDy[7] = {8, 8, 8, 4, 4, 2, 2};
  int64_t size = 0;
  for (int pass = 0; pass < 7; ++pass) {
    const int64_t columns = width > kX0[pass] ? (width - kX0[pass] + kDx[pass] - 1) / kDx[pass] : 0;
    const int64_t rows = height > kY0[pass] ? (height - kY0[pass] + kDy[pass] - 1) / kDy[pass] : 0;
    if (columns > 0 && rows > 0) size += rows * (1 + RowBytes(columns, layout));
  }
  return size;
}

absl::Status CheckPngImageData(const std::string& png, const PngLayout& layout,
                               PngDecodeStats* stats) {
  PngDecodeStats unused;
  if (stats == nullptr) stats = &unused;
  const auto* data = reinterpret_cast<const unsigned char*>(png.data());
  BoundedInflater inflater(PngImageDataSize(layout));
  bool seen_idat = false;
  bool idat_done = false;
  size_t pos = kSignatureBytes;
  while (pos + kChunkOverhead <= png.size()) {
    const uint32_t length = ReadBigEndian32(data + pos);
    if (length > png.size() - pos - kChunkOverhead) {
      return absl::InvalidArgumentError(
          absl::StrCat("the chunk at byte ", pos, " is truncated (length ", length, ")"));
    }
    const bool idat = std::memcmp(data + pos + 4, "IDAT", 4) == 0;
    if (idat) {
      if (idat_done) {
        return absl::InvalidArgumentError(
            absl::StrCat("the IDAT chunk at byte ", pos, " does not follow the other IDAT chunks"));
      }
      seen_idat = true;
      if (auto s = inflater.Feed(data + pos + 8, length, stats); !s.ok()) return s;
    } else if (seen_idat) {
      idat_done = true;
    }
    if (std::memcmp(data + pos + 4, "IEND", 4) == 0) break;
    pos += kChunkOverhead + length;
  }
  if (!seen_idat) return absl::InvalidArgumentError("no image data (IDAT chunk)");
  return inflater.Finish();
}

}  // namespace swarmplan::map_io_internal
