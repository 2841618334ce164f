// EncodeGray16Png: a PNG (ISO/IEC 15948) of one 16-bit grey channel, non-interlaced: the
// signature, IHDR, one IDAT holding the zlib stream of the rows (each behind filter byte 0, "none":
// rendered depth and label images compress well either way; samples big-endian as PNG stores them)
// and IEND, each chunk with its CRC-32. Deflate and CRC-32 by libdeflate (zlib_compressor.h), level
// 2, as the 8-bit images are: about half the time libpng with zlib's level 1 took (docs/benchmarks.md,
// "Dataset samples").
#include "image/gray16_png.h"

#include <libdeflate.h>

#include <string>
#include <string_view>

#include "common/atomic_file.h"
#include "common/error.h"
#include "image/zlib_compressor.h"

namespace urdfsnap::image {

namespace {

void AppendBigEndian(std::vector<std::uint8_t>& bytes, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<std::uint8_t>(value >> shift));
}

// Appends the chunk of `type` whose data are the `size` bytes already at the end of `bytes`, placed
// there behind 8 bytes reserved for its length and type (from `start`): fills those in, adds the CRC.
void CloseChunk(std::vector<std::uint8_t>& bytes, std::size_t start, std::string_view type) {
  const auto size = static_cast<std::uint32_t>(bytes.size() - start - 8);
  for (int k = 0; k < 4; ++k) {
    bytes[start + k] = static_cast<std::uint8_t>(size >> (24 - 8 * k));
    bytes[start + 4 + k] = static_cast<std::uint8_t>(type[k]);
  }
  AppendBigEndian(bytes, libdeflate_crc32(0, bytes.data() + start + 4, size + 4));
}

}  // namespace

std::vector<std::uint8_t> EncodeGray16Png(const Gray16Image& image) {
  const int width = image.width, height = image.height;
  const std::vector<std::uint16_t>& values = image.values;
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide ||
      values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw Error("EncodeGray16Png: " + std::to_string(values.size()) + " values do not make a " +
                std::to_string(width) + "x" + std::to_string(height) + " image");
  }
  const std::size_t row_bytes = 1 + 2 * static_cast<std::size_t>(width);
  std::vector<std::uint8_t> rows(row_bytes * height);
  for (int y = 0; y < height; ++y) {
    std::uint8_t* row = rows.data() + y * row_bytes;
    row[0] = 0;   // filter: none
    const std::uint16_t* samples = values.data() + static_cast<std::size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      row[1 + 2 * x] = static_cast<std::uint8_t>(samples[x] >> 8);
      row[2 + 2 * x] = static_cast<std::uint8_t>(samples[x]);
    }
  }
  libdeflate_compressor* compressor = ThreadZlibCompressor();
  if (compressor == nullptr) throw Error("EncodeGray16Png: out of memory");
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, rows.size());

  std::vector<std::uint8_t> bytes = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  bytes.reserve(bytes.size() + 25 + 12 + bound + 12);
  std::size_t start = bytes.size();
  bytes.resize(start + 8);
  AppendBigEndian(bytes, static_cast<std::uint32_t>(width));
  AppendBigEndian(bytes, static_cast<std::uint32_t>(height));
  bytes.insert(bytes.end(), {16, 0, 0, 0, 0});   // bit depth 16, grey, deflate, no filter method, no interlace
  CloseChunk(bytes, start, "IHDR");

  start = bytes.size();
  bytes.resize(start + 8 + bound);
  const std::size_t size = libdeflate_zlib_compress(compressor, rows.data(), rows.size(), bytes.data() + start + 8, bound);
  if (size == 0) throw Error("EncodeGray16Png: out of memory");   // cannot happen with the bound's room
  bytes.resize(start + 8 + size);
  CloseChunk(bytes, start, "IDAT");

  start = bytes.size();
  bytes.resize(start + 8);
  CloseChunk(bytes, start, "IEND");
  return bytes;
}

void WriteGray16Png(const Gray16Image& image, const std::string& path) {
  const std::vector<std::uint8_t> png = EncodeGray16Png(image);
  WriteFileAtomically(path, {reinterpret_cast<const char*>(png.data()), png.size()});
}

}  // namespace urdfsnap::image
