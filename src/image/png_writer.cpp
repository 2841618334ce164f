// PNG encoding: stb_image_write compiled here, privately (STB_IMAGE_WRITE_STATIC), with zlib's
// compress2 at level 1 as its deflate and the row filter off.
#include "image/png_writer.h"

#include <zlib.h>

#include <cstdlib>
#include <string_view>

#include "common/error.h"
#include "common/atomic_file.h"

namespace {

// stb's PNG writer calls this in place of its own deflate (about 10x slower); `quality` is stb's
// compression level, which level 1 overrides: on rendered images (large flat areas) it gives files
// about as small in a fraction of the time. The result is released by stb with free().
unsigned char* ZlibCompressFast(unsigned char* data, int data_len, int* out_len, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(data_len));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (out == nullptr) return nullptr;
  if (compress2(out, &size, data, static_cast<uLong>(data_len), 1) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_len = static_cast<int>(size);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS ZlibCompressFast
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
