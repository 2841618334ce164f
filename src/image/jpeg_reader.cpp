// DecodeJpeg: the size read from the header first, then stb_image compiled here, privately
// (STB_IMAGE_STATIC), for JPEG only (png_reader.cpp compiles its own copy for PNG).
#include "image/jpeg_reader.h"

#include <cstdint>

#include "common/error.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 16384  // stb's own guard, the same as kMaxImageSide
#include <stb/stb_image.h>

namespace urdfsnap::image {

static_assert(STBI_MAX_DIMENSIONS == kMaxImageSide);

bool LooksLikeJpeg(std::string_view bytes) {
  return bytes.size() >= 3 && static_cast<std::uint8_t>(bytes[0]) == 0xFF &&
         static_cast<std::uint8_t>(bytes[1]) == 0xD8 && static_cast<std::uint8_t>(bytes[2]) == 0xFF;
}

Image DecodeJpeg(std::string_view bytes, const std::string& name) {
  if (!LooksLikeJpeg(bytes)) throw Error(name + ": not a JPEG (no start-of-image marker)");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = bytes.size() > 0x7fffffff ? 0x7fffffff : static_cast<int>(bytes.size());
  Image image;
  int channels = 0;
  // stb keeps the reason of the last failure per thread: clear it, so that a message never
  // carries an earlier image's reason
  stbi__g_failure_reason = nullptr;
  if (!stbi_info_from_memory(data, size, &image.width, &image.height, &channels)) {
    const char* reason = stbi_failure_reason();
    throw Error(name + ": cannot read the JPEG header: " + (reason ? reason : "corrupt data"));
  }
  CheckImageSize(image.width, image.height, name);
  stbi_uc* pixels = stbi_load_from_memory(data, size, &image.width, &image.height, &channels, 3);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    throw Error(name + ": cannot decode JPEG: " + (reason ? reason : "corrupt image data"));
  }
  image.rgb.assign(pixels, pixels + std::size_t(image.width) * image.height * 3);
  stbi_image_free(pixels);
  return image;
}

}  // namespace urdfsnap::image
