// PNG encoding: stb_image_write compiled here, privately (STB_IMAGE_WRITE_STATIC), with
// libdeflate at level 2 as its deflate and the row filter off.
#include "image/png_writer.h"

#include <libdeflate.h>

#include <cstdlib>
#include <string_view>

#include "common/error.h"
#include "common/atomic_file.h"
#include "image/zlib_compressor.h"

namespace {

// stb's PNG writer calls this in place of its own deflate (about 10x slower than zlib's level 1);
// `quality` is stb's compression level, which this ignores. Returns a zlib stream (header, deflate,
// Adler-32) that stb releases with free(), or null when out of memory.
unsigned char* DeflateFast(unsigned char* data, int data_len, int* out_len, int /*quality*/) {
  libdeflate_compressor* compressor = urdfsnap::image::ThreadZlibCompressor();
  if (compressor == nullptr) return nullptr;
  const size_t bound = libdeflate_zlib_compress_bound(compressor, static_cast<size_t>(data_len));
  auto* out = static_cast<unsigned char*>(std::malloc(bound));
  if (out == nullptr) return nullptr;
  const size_t size = libdeflate_zlib_compress(compressor, data, static_cast<size_t>(data_len), out, bound);
  if (size == 0) {   // cannot happen with the bound's room; treated as out of memory
    std::free(out);
    return nullptr;
  }
  *out_len = static_cast<int>(size);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS DeflateFast
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

namespace urdfsnap::image {
namespace {

// stb reads its filter choice from this file-local variable; filter 0 ("none") skips stb's
// per-row trial of all five filters, the larger half of its time, at little cost in size here.
[[maybe_unused]] const bool kRowFilterOff = [] {
  stbi_write_force_png_filter = 0;
  return true;
}();

// stb's PNG bytes of `channels` 8-bit channels per pixel.
std::vector<std::uint8_t> Encode(const std::uint8_t* pixels, int width, int height, int channels,
                                 const char* role) {
  int size = 0;
  unsigned char* png = stbi_write_png_to_mem(pixels, width * channels, width, height, channels, &size);
  if (png == nullptr) {
    throw Error(std::string(role) + ": out of memory encoding a " + SizeText(width, height) + " image");
  }
  std::vector<std::uint8_t> bytes(png, png + size);
  std::free(png);
  return bytes;
}

void WriteBytes(const std::vector<std::uint8_t>& png, const std::string& path) {
  WriteFileAtomically(path, {reinterpret_cast<const char*>(png.data()), png.size()});
}

}  // namespace

std::vector<std::uint8_t> EncodePng(const Image& image) {
  CheckImage(image, "EncodePng");
  return Encode(image.rgb.data(), image.width, image.height, 3, "EncodePng");
}

void WritePng(const Image& image, const std::string& path) { WriteBytes(EncodePng(image), path); }

std::vector<std::uint8_t> EncodeGray8Png(const Gray8Image& image) {
  CheckImageSize(image.width, image.height, "EncodeGray8Png");
  if (image.values.size() != static_cast<size_t>(image.width) * image.height) {
    throw Error("EncodeGray8Png: " + std::to_string(image.values.size()) + " values for a " +
                SizeText(image.width, image.height) + " image");
  }
  return Encode(image.values.data(), image.width, image.height, 1, "EncodeGray8Png");
}

void WriteGray8Png(const Gray8Image& image, const std::string& path) { WriteBytes(EncodeGray8Png(image), path); }

}  // namespace urdfsnap::image
