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

}  // namespace

std::vector<std::uint8_t> EncodePng(const Image& image) {
  CheckImage(image, "EncodePng");
  int size = 0;
  unsigned char* png =
      stbi_write_png_to_mem(image.rgb.data(), image.width * 3, image.width, image.height, 3, &size);
  if (png == nullptr) {
    throw Error("EncodePng: out of memory encoding a " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " image");
  }
  std::vector<std::uint8_t> bytes(png, png + size);
  std::free(png);
  return bytes;
}

void WritePng(const Image& image, const std::string& path) {
  const std::vector<std::uint8_t> png = EncodePng(image);
  WriteFileAtomically(path, {reinterpret_cast<const char*>(png.data()), png.size()});
}

}  // namespace urdfsnap::image
