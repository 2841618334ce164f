// EncodeGray16Png: libpng's write API into memory, big-endian samples as PNG stores them, with
// libpng's zlib at level 1 and no row filter (rendered images compress well either way).
#include "image/gray16_png.h"

#include <png.h>

#include <csetjmp>
#include <string>

#include "common/atomic_file.h"
#include "common/error.h"

namespace urdfsnap::image {

namespace {

void Append(png_structp png, png_bytep data, png_size_t length) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  bytes->insert(bytes->end(), data, data + length);
}

// libpng reports errors by longjmp; the message is kept for the exception thrown afterwards.
void Fail(png_structp png, png_const_charp message) {
  auto* reason = static_cast<std::string*>(png_get_error_ptr(png));
  *reason = message;
  png_longjmp(png, 1);
}

// Writes the image through `png`; false (with the reason set by Fail) when libpng failed. No
// object with a destructor lives in this function: libpng's longjmp would skip it.
bool WriteImage(png_structp png, png_infop info, int width, int height, const std::uint16_t* values) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 16,
               PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 1);
  png_set_filter(png, 0, PNG_FILTER_NONE);
  png_write_info(png, info);
  png_set_swap(png);   // our samples are in the machine's (little-endian) order
  for (int y = 0; y < height; ++y) {
    png_write_row(png, reinterpret_cast<png_const_bytep>(values + static_cast<std::size_t>(y) * width));
  }
  png_write_end(png, nullptr);
  return true;
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
  std::vector<std::uint8_t> bytes;
  std::string reason = "out of memory";
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &reason, Fail, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  bool written = false;
  if (info) {
    png_set_write_fn(png, &bytes, Append, nullptr);
    written = WriteImage(png, info, width, height, values.data());
  }
  png_destroy_write_struct(&png, &info);
  if (!written) throw Error("EncodeGray16Png: " + reason);
  return bytes;
}

void WriteGray16Png(const Gray16Image& image, const std::string& path) {
  const std::vector<std::uint8_t> png = EncodeGray16Png(image);
  WriteFileAtomically(path, {reinterpret_cast<const char*>(png.data()), png.size()});
}

}  // namespace urdfsnap::image
