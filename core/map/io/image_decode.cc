#include "core/map/io/image_decode.h"

#include <png.h>

#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "absl/strings/str_cat.h"
#include "core/map/io/png_image_data.h"
#include "core/map/io/text_util.h"

namespace swarmplan {
namespace {

using map_io_internal::InvalidAt;

// ---- PGM ----------------------------------------------------------------------------------

// Tokens of a PGM header or P2 body: whitespace separated, '#' comments to the end of a line.
class PgmTokens {
 public:
  explicit PgmTokens(const std::string& bytes) : bytes_(bytes) {}

  bool Next(std::string_view* token) {
    while (pos_ < bytes_.size()) {
      const char c = bytes_[pos_];
      if (c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      } else if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else {
        break;
      }
    }
    if (pos_ >= bytes_.size()) return false;
    const size_t start = pos_;
    while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_])) &&
           bytes_[pos_] != '#') {
      ++pos_;
    }
    *token = std::string_view(bytes_).substr(start, pos_ - start);
    token_line_ = line_;
    return true;
  }
  // The line of the last token (the line to blame when the data ends too early).
  int line() const { return token_line_; }
  size_t pos() const { return pos_; }

 private:
  const std::string& bytes_;
  size_t pos_ = 2;  // after the magic number
  int line_ = 1;
  int token_line_ = 1;
};

absl::Status ReadHeaderNumber(const std::string& file, PgmTokens& tokens, const char* field,
                              int64_t max, int64_t* out) {
  std::string_view token;
  if (!tokens.Next(&token)) {
    return InvalidAt(file, tokens.line(), absl::StrCat("PGM header ends before its ", field));
  }
  int64_t value = 0;
  if (!map_io_internal::ParseInt(token, &value) || value < 1 || value > max) {
    return InvalidAt(file, tokens.line(),
                     absl::StrCat("PGM ", field, " must be an integer in 1..", max, ", got ",
                                  map_io_internal::Quote(token)));
  }
  *out = value;
  return absl::OkStatus();
}

// ---- PNG ----------------------------------------------------------------------------------

// Everything the libpng calls touch lives here, in plain C storage: libpng reports errors with
// longjmp, which must not skip C++ destructors.
struct PngRead {
  const unsigned char* data = nullptr;
  size_t size = 0;
  size_t offset = 0;
  int64_t max_cells = 0;
  png_structp png = nullptr;
  png_infop info = nullptr;
  unsigned char* pixels = nullptr;  // malloc'ed, height * rowbytes
  png_bytep* rows = nullptr;        // malloc'ed
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int channels = 0;
  int bit_depth = 0;
  size_t rowbytes = 0;
  map_io_internal::PngLayout layout;
  bool too_large = false;
  char error[200] = {};
};

void PngError(png_structp png, png_const_charp message) {
  auto* read = static_cast<PngRead*>(png_get_error_ptr(png));
  std::snprintf(read->error, sizeof(read->error), "%s", message);
  png_longjmp(png, 1);
}

void PngWarning(png_structp, png_const_charp) {}

void PngReadData(png_structp png, png_bytep out, size_t length) {
  auto* read = static_cast<PngRead*>(png_get_io_ptr(png));
  if (length > read->size - read->offset) png_error(png, "the PNG data is truncated");
  std::memcpy(out, read->data + read->offset, length);
  read->offset += length;
}

// The ancillary chunks the decoder never needs: libpng skips them unread (no text or profile
// is inflated). tRNS is kept: it becomes alpha.
constexpr png_byte kIgnoredChunks[] =
    "bKGD\0cHRM\0eXIf\0gAMA\0hIST\0iCCP\0iTXt\0oFFs\0pCAL\0pHYs\0sBIT\0sCAL\0sPLT\0sRGB\0"
    "tEXt\0tIME\0zTXt";
constexpr int kIgnoredChunkCount = sizeof(kIgnoredChunks) / 5;
constexpr png_alloc_size_t kMaxChunkBytes = 1 << 20;

// Reads the header up to the image data. Returns false with read->error set on failure. No C++
// objects with destructors live in this frame, so the longjmp from libpng is safe.
bool ReadPngHeader(PngRead* read) {
  read->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, read, PngError, PngWarning);
  if (read->png == nullptr) {
    std::snprintf(read->error, sizeof(read->error), "cannot start the PNG decoder");
    return false;
  }
  read->info = png_create_info_struct(read->png);
  if (read->info == nullptr) {
    std::snprintf(read->error, sizeof(read->error), "cannot start the PNG decoder");
    return false;
  }
  if (setjmp(png_jmpbuf(read->png))) return false;
  png_set_read_fn(read->png, read, PngReadData);
  png_set_user_limits(read->png, 0x7fffffff, 0x7fffffff);
  png_set_chunk_malloc_max(read->png, kMaxChunkBytes);
  png_set_keep_unknown_chunks(read->png, PNG_HANDLE_CHUNK_NEVER, nullptr, 0);
  png_set_keep_unknown_chunks(read->png, PNG_HANDLE_CHUNK_NEVER, kIgnoredChunks,
                              kIgnoredChunkCount);
  png_read_info(read->png, read->info);
  read->width = png_get_image_width(read->png, read->info);
  read->height = png_get_image_height(read->png, read->info);
  if (read->width == 0 || read->height == 0 ||
      static_cast<int64_t>(read->width) > read->max_cells / static_cast<int64_t>(read->height)) {
    read->too_large = true;
    std::snprintf(read->error, sizeof(read->error), "%u x %u pixels exceed the limit of %lld cells",
                  read->width, read->height, static_cast<long long>(read->max_cells));
    return false;
  }
  read->layout.width = read->width;
  read->layout.height = read->height;
  read->layout.bit_depth = png_get_bit_depth(read->png, read->info);
  read->layout.channels = png_get_channels(read->png, read->info);
  read->layout.interlaced = png_get_interlace_type(read->png, read->info) != PNG_INTERLACE_NONE;
  return true;
}

// Decodes the rows once the image data has passed CheckPngImageData. Same contract as above.
bool ReadPngRows(PngRead* read) {
  if (setjmp(png_jmpbuf(read->png))) return false;
  png_set_expand(read->png);  // palette -> RGB, grey < 8 bits -> 8 bits, tRNS -> alpha
  png_set_interlace_handling(read->png);
  png_read_update_info(read->png, read->info);
  read->channels = png_get_channels(read->png, read->info);
  read->bit_depth = png_get_bit_depth(read->png, read->info);
  read->rowbytes = png_get_rowbytes(read->png, read->info);
  read->pixels = static_cast<unsigned char*>(std::malloc(read->rowbytes * read->height));
  read->rows = static_cast<png_bytep*>(std::malloc(sizeof(png_bytep) * read->height));
  if (read->pixels == nullptr || read->rows == nullptr) {
    std::snprintf(read->error, sizeof(read->error), "out of memory");
    return false;
  }
  for (png_uint_32 y = 0; y < read->height; ++y) read->rows[y] = read->pixels + y * read->rowbytes;
  png_read_image(read->png, read->rows);
  return true;
}

}  // namespace

absl::StatusOr<DecodedImage> DecodePgm(const std::string& file, const std::string& bytes,
                                       const MapLimits& limits) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '5')) {
    return InvalidAt(file, 1, "not a PGM image: expected the magic number P2 or P5");
  }
  const bool binary = bytes[1] == '5';
  PgmTokens tokens(bytes);
  int64_t width = 0, height = 0, max_value = 0;
  if (auto s = ReadHeaderNumber(file, tokens, "width", 1 << 30, &width); !s.ok()) return s;
  if (auto s = ReadHeaderNumber(file, tokens, "height", 1 << 30, &height); !s.ok()) return s;
  if (auto s = ReadHeaderNumber(file, tokens, "maxval", 65535, &max_value); !s.ok()) return s;
  if (auto s = map_io_internal::CheckCellCount(file, width, height, limits); !s.ok()) return s;
  const int64_t count = width * height;
  const int sample_bytes = max_value > 255 ? 2 : 1;
  const size_t data_start = tokens.pos() + 1;  // one whitespace character after maxval
  if (binary && (data_start > bytes.size() ||
                 static_cast<int64_t>(bytes.size() - data_start) < count * sample_bytes)) {
    return map_io_internal::Invalid(
        file, absl::StrCat("PGM pixel data is truncated: ", width, " x ", height, " pixels need ",
                           count * sample_bytes, " bytes, the file has ",
                           data_start > bytes.size() ? 0 : bytes.size() - data_start));
  }
  if (!binary && count > static_cast<int64_t>(bytes.size()) / 2 + 1) {
    return map_io_internal::Invalid(
        file, absl::StrCat("PGM pixel data is truncated: ", width, " x ", height,
                           " pixels cannot fit in ", bytes.size(), " bytes"));
  }
  DecodedImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.max_value = static_cast<int>(max_value);
  image.channel_sum.resize(count);
  for (int64_t i = 0; i < count; ++i) {
    uint32_t value = 0;
    if (binary) {
      const auto* p =
          reinterpret_cast<const unsigned char*>(bytes.data()) + data_start + i * sample_bytes;
      value = sample_bytes == 2 ? (uint32_t{p[0]} << 8) | p[1] : p[0];
      if (value > max_value) {
        return map_io_internal::Invalid(
            file, absl::StrCat("pixel ", i % width, ",", i / width, " (column, row) has value ",
                               value, " above maxval ", max_value));
      }
    } else {
      std::string_view token;
      if (!tokens.Next(&token)) {
        return InvalidAt(file, tokens.line(),
                         absl::StrCat("PGM pixel data ends after ", i, " of ", count, " values"));
      }
      int64_t v = 0;
      if (!map_io_internal::ParseInt(token, &v) || v < 0 || v > max_value) {
        return InvalidAt(file, tokens.line(),
                         absl::StrCat("pixel ", i % width, ",", i / width,
                                      " (column, row) must be an integer in 0..", max_value,
                                      ", got ", map_io_internal::Quote(token)));
      }
      value = static_cast<uint32_t>(v);
    }
    image.channel_sum[i] = value;
  }
  return image;
}

absl::StatusOr<DecodedImage> DecodePng(const std::string& file, const std::string& bytes,
                                       const MapLimits& limits,
                                       map_io_internal::PngDecodeStats* stats) {
  PngRead read;
  read.data = reinterpret_cast<const unsigned char*>(bytes.data());
  read.size = bytes.size();
  read.max_cells = limits.max_cells;
  bool ok = ReadPngHeader(&read);
  absl::Status image_data;
  if (ok) image_data = map_io_internal::CheckPngImageData(bytes, read.layout, stats);
  if (ok && image_data.ok()) ok = ReadPngRows(&read);
  absl::StatusOr<DecodedImage> result;
  if (!image_data.ok()) {
    result = absl::InvalidArgumentError(absl::StrCat(file, ": bad PNG: ", image_data.message()));
  } else if (!ok) {
    result = read.too_large
                 ? absl::ResourceExhaustedError(absl::StrCat(file, ": PNG of ", read.error))
                 : absl::InvalidArgumentError(absl::StrCat(file, ": bad PNG: ", read.error));
  } else {
    DecodedImage image;
    image.width = static_cast<int>(read.width);
    image.height = static_cast<int>(read.height);
    const bool has_alpha = read.channels == 2 || read.channels == 4;
    image.colour_channels = read.channels - (has_alpha ? 1 : 0);
    image.max_value = read.bit_depth == 16 ? 65535 : 255;
    const size_t count = static_cast<size_t>(read.width) * read.height;
    image.channel_sum.resize(count);
    if (has_alpha) image.alpha.resize(count);
    const int sample_bytes = read.bit_depth == 16 ? 2 : 1;
    for (png_uint_32 y = 0; y < read.height; ++y) {
      const unsigned char* row = read.rows[y];
      for (png_uint_32 x = 0; x < read.width; ++x) {
        const unsigned char* p = row + static_cast<size_t>(x) * read.channels * sample_bytes;
        auto sample = [&](int c) -> uint32_t {
          const unsigned char* s = p + c * sample_bytes;
          return sample_bytes == 2 ? (uint32_t{s[0]} << 8) | s[1] : s[0];
        };
        const size_t i = static_cast<size_t>(y) * read.width + x;
        uint32_t sum = 0;
        for (int c = 0; c < image.colour_channels; ++c) sum += sample(c);
        image.channel_sum[i] = sum;
        if (has_alpha) image.alpha[i] = static_cast<uint16_t>(sample(image.colour_channels));
      }
    }
    result = std::move(image);
  }
  png_destroy_read_struct(read.png ? &read.png : nullptr, read.info ? &read.info : nullptr,
                          nullptr);
  std::free(read.rows);
  std::free(read.pixels);
  return result;
}

absl::StatusOr<DecodedImage> DecodeImage(const std::string& file, const std::string& bytes,
                                         const MapLimits& limits) {
  if (auto s = map_io_internal::CheckFileSize(file, bytes.size(), limits); !s.ok()) return s;
  static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPngSignature, 8) == 0) {
    return DecodePng(file, bytes, limits);
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5')) {
    return DecodePgm(file, bytes, limits);
  }
  return map_io_internal::Invalid(file, "not a PGM (P2/P5) or PNG image");
}

}  // namespace swarmplan
