// PNG decoding stops at the declared image size: image data that inflates beyond it, trails the
// compressed stream or comes in extra IDAT chunks is refused, after bounded work.

#include <png.h>
#include <zlib.h>

#include <string>
#include <vector>

#include "core/map/io/image_decode.h"
#include "core/map/io/map_io.h"
#include "core/map/io/png_image_data.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using map_io_internal::PngDecodeStats;
using ::testing::HasSubstr;

void AppendBigEndian32(std::string* out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<char>(v >> shift));
}

void AppendChunk(std::string* png, const char* type, const std::string& data) {
  AppendBigEndian32(png, static_cast<uint32_t>(data.size()));
  const std::string typed = std::string(type, 4) + data;
  png->append(typed);
  AppendBigEndian32(png, crc32(0, reinterpret_cast<const Bytef*>(typed.data()), typed.size()));
}

// An 8-bit grey PNG of width x height pixels whose IDAT chunks (at most 64 KiB each) hold
// `image_data`, a zlib stream given as is.
std::string GreyPng(uint32_t width, uint32_t height, const std::string& image_data) {
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  AppendBigEndian32(&header, width);
  AppendBigEndian32(&header, height);
  header +=
      std::string("\x08\x00\x00\x00\x00", 5);  // depth 8, grey, deflate, filter 0, no interlace
  AppendChunk(&png, "IHDR", header);
  for (size_t at = 0; at < image_data.size(); at += 65536) {
    AppendChunk(&png, "IDAT", image_data.substr(at, 65536));
  }
  AppendChunk(&png, "IEND", "");
  return png;
}

std::string Deflate(z_stream* stream, const std::string& input, int flush) {
  std::string out;
  std::vector<unsigned char> buffer(1 << 16);
  stream->next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
  stream->avail_in = static_cast<uInt>(input.size());
  do {
    stream->next_out = buffer.data();
    stream->avail_out = static_cast<uInt>(buffer.size());
    deflate(stream, flush);
    out.append(reinterpret_cast<char*>(buffer.data()), buffer.size() - stream->avail_out);
  } while (stream->avail_out == 0);
  return out;
}

// A zlib stream of `prefix` zero bytes followed by `repeats` MiB of zeros, made without
// compressing them all: after a full flush the compressor starts afresh, so the MiB compresses
// to the same bytes every time and is repeated; the checksum is combined to match.
std::string ZerosStream(size_t prefix, int repeats) {
  z_stream stream{};
  deflateInit(&stream, Z_BEST_COMPRESSION);
  const std::string head(prefix, '\0');
  const std::string mib(1 << 20, '\0');
  std::string out = Deflate(&stream, head, Z_FULL_FLUSH);
  const std::string block = Deflate(&stream, mib, Z_FULL_FLUSH);
  std::string tail = Deflate(&stream, "", Z_FINISH);
  deflateEnd(&stream);
  uLong adler = adler32(1, reinterpret_cast<const Bytef*>(head.data()), head.size());
  const uLong mib_adler = adler32(1, reinterpret_cast<const Bytef*>(mib.data()), mib.size());
  for (int i = 0; i < repeats; ++i) {
    out += block;
    adler = adler32_combine(adler, mib_adler, mib.size());
  }
  tail.resize(tail.size() - 4);
  AppendBigEndian32(&tail, static_cast<uint32_t>(adler));
  return out + tail;
}

std::string Compress(const std::string& raw) {
  uLongf size = compressBound(raw.size());
  std::string out(size, '\0');
  compress(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
           raw.size());
  out.resize(size);
  return out;
}

constexpr size_t kRows16x16 = 16 * (1 + 16);  // a filter byte per row

TEST(MapIoPngBoundTest, ZerosStreamIsTheRightSize) {
  // The construction itself, checked on a small instance by inflating it fully.
  const std::string stream = ZerosStream(kRows16x16, 3);
  std::string out(kRows16x16 + (3 << 20) + 1, '\x7f');
  uLongf size = out.size();
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &size,
                       reinterpret_cast<const Bytef*>(stream.data()), stream.size()),
            Z_OK);
  EXPECT_EQ(size, kRows16x16 + (3 << 20));
  EXPECT_EQ(out.find_first_not_of('\0'), size);
}

TEST(MapIoPngBoundTest, RefusesImageDataInflatingFarBeyondTheDeclaredSize) {
  // 16 x 16 pixels declared; the image data inflates to 272 bytes + 1 GiB from about 1 MB.
  const std::string png = GreyPng(16, 16, ZerosStream(kRows16x16, 1024));
  ASSERT_LT(png.size(), 2u << 20);
  PngDecodeStats stats;
  auto image = DecodePng("bomb.png", png, MapLimits{}, &stats);
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(image.status().message(), HasSubstr("bomb.png: bad PNG"));
  EXPECT_THAT(image.status().message(),
              HasSubstr("inflates to more than the 272 bytes the declared size needs"));
  // The work: one byte past the declared size inflated, a few KB of the file read.
  EXPECT_LE(stats.inflated_bytes, static_cast<int64_t>(kRows16x16) + 1);
  EXPECT_LE(stats.compressed_bytes, 4096);

  auto map = ParseMap("png", {MapFile{"bomb.png", png}});
  ASSERT_FALSE(map.ok());
  EXPECT_EQ(map.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(map.status().message(), HasSubstr("bomb.png: bad PNG"));
}

TEST(MapIoPngBoundTest, DecodesImageDataOfExactlyTheDeclaredSize) {
  PngDecodeStats stats;
  auto image = DecodePng("ok.png", GreyPng(16, 16, Compress(std::string(kRows16x16, '\0'))),
                         MapLimits{}, &stats);
  ASSERT_TRUE(image.ok()) << image.status();
  EXPECT_EQ(image->width, 16);
  EXPECT_EQ(image->Grey(0), 0.0);
  EXPECT_EQ(stats.inflated_bytes, static_cast<int64_t>(kRows16x16));
}

TEST(MapIoPngBoundTest, RefusesExtraOrMissingImageData) {
  const std::string rows(kRows16x16, '\0');
  struct Case {
    std::string png;
    std::string message;
  };
  std::string extra_idat = GreyPng(16, 16, Compress(rows));
  const std::string iend = extra_idat.substr(extra_idat.size() - 12);
  extra_idat.resize(extra_idat.size() - 12);
  AppendChunk(&extra_idat, "IDAT", Compress("more"));
  extra_idat += iend;
  std::string split = GreyPng(16, 16, Compress(rows));
  split.resize(split.size() - 12);
  AppendChunk(&split, "tEXt", std::string("Comment\0x", 9));
  AppendChunk(&split, "IDAT", "x");
  split += iend;
  const std::string truncated = Compress(rows);
  const Case cases[] = {
      {GreyPng(16, 16, Compress(rows) + "trailing"),
       "extra image data after the end of the compressed stream (8 bytes)"},
      {extra_idat, "extra image data after the end of the compressed stream (an IDAT chunk"},
      {split, "does not follow the other IDAT chunks"},
      {GreyPng(16, 16, Compress(rows + "x")), "inflates to more than the 272 bytes"},
      {GreyPng(16, 16, Compress(std::string(kRows16x16 - 1, '\0'))),
       "not enough image data: 271 of the 272 bytes"},
      {GreyPng(16, 16, truncated.substr(0, 4)), "not enough image data"},
      {GreyPng(16, 16, truncated.substr(0, truncated.size() - 4)),
       "the compressed image data is truncated"},
      {GreyPng(16, 16, "not zlib"), "corrupt image data"},
  };
  for (const Case& c : cases) {
    auto image = DecodePng("bad.png", c.png, MapLimits{});
    ASSERT_FALSE(image.ok()) << c.message;
    EXPECT_EQ(image.status().code(), absl::StatusCode::kInvalidArgument) << image.status();
    EXPECT_THAT(image.status().message(), HasSubstr("bad.png: bad PNG: "));
    EXPECT_THAT(image.status().message(), HasSubstr(c.message));
  }
}

// libpng writes a PNG in memory, interlaced or not.
void AppendPngData(png_structp png, png_bytep data, size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), size);
}

std::string WritePng(int width, int height, int colour_type, int bit_depth, bool interlaced,
                     const std::vector<unsigned char>& pixels) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(png, &out, AppendPngData, nullptr);
  png_set_IHDR(png, info, width, height, bit_depth, colour_type,
               interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const size_t row_bytes = png_get_rowbytes(png, info);
  std::vector<png_bytep> rows(height);
  for (int y = 0; y < height; ++y) {
    rows[y] = const_cast<png_bytep>(pixels.data()) + y * row_bytes;
  }
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

TEST(MapIoPngBoundTest, InterlacedAndPackedImagesDecodeAsTheirPlainTwins) {
  // 7 x 5 pixels: every Adam7 pass is partly empty or short.
  std::vector<unsigned char> rgb;
  for (int i = 0; i < 7 * 5 * 3; ++i) rgb.push_back(static_cast<unsigned char>(i * 37));
  auto plain = DecodePng("plain.png", WritePng(7, 5, PNG_COLOR_TYPE_RGB, 8, false, rgb), {});
  auto interlaced = DecodePng("adam7.png", WritePng(7, 5, PNG_COLOR_TYPE_RGB, 8, true, rgb), {});
  ASSERT_TRUE(plain.ok()) << plain.status();
  ASSERT_TRUE(interlaced.ok()) << interlaced.status();
  EXPECT_EQ(plain->channel_sum, interlaced->channel_sum);
  // 1-bit grey: 7 pixels in one byte per row.
  const std::vector<unsigned char> bits = {0xa0, 0x50, 0xff, 0x00, 0x80};
  auto packed = DecodePng("bits.png", WritePng(7, 5, PNG_COLOR_TYPE_GRAY, 1, true, bits), {});
  ASSERT_TRUE(packed.ok()) << packed.status();
  EXPECT_EQ(packed->Grey(0), 255.0);
  EXPECT_EQ(packed->Grey(1), 0.0);
  EXPECT_EQ(packed->Grey(7 + 1), 255.0);
}

TEST(MapIoPngBoundTest, ImageDataSizeCountsEveryPassRow) {
  map_io_internal::PngLayout layout;
  layout.width = 16;
  layout.height = 16;
  EXPECT_EQ(map_io_internal::PngImageDataSize(layout), 272);
  layout.interlaced = true;
  layout.width = 1;
  layout.height = 1;
  EXPECT_EQ(map_io_internal::PngImageDataSize(layout), 2);  // only pass 1 has the pixel
  layout.width = 7;
  layout.height = 5;
  layout.channels = 3;
  // Passes (columns x rows): 1x1, 1x1, 2x1, 2x2, 4x1, 3x3, 7x2.
  EXPECT_EQ(map_io_internal::PngImageDataSize(layout),
            (1 + 3) + (1 + 3) + (1 + 6) + 2 * (1 + 6) + (1 + 12) + 3 * (1 + 9) + 2 * (1 + 21));
}

}  // namespace
}  // namespace swarmplan
