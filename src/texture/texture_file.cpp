// Texture decoding (JPEG as FreeImage decodes it for Ogre, the other formats with stb_image,
// compiled here privately) and a process-wide cache.
#include "texture/texture_file.h"

#include <filesystem>
#include <utility>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/shared_cache.h"
#include "image/image.h"
#include "texture/jpeg_texture.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 16384   // the same as image::kMaxImageSide
#include <stb/stb_image.h>

namespace urdfsnap::texture {

namespace {

static_assert(STBI_MAX_DIMENSIONS == image::kMaxImageSide);

// Largest texture file read: a 16384x16384 RGBA image with room to spare for its encoding.
constexpr std::size_t kMaxTextureFileBytes = std::size_t{1} << 30;

std::shared_ptr<const TextureImage> Decode(const std::string& path) {
  std::string bytes;
  try {
    bytes = ReadFileBounded(path, kMaxTextureFileBytes);
  } catch (const FileReadError& e) {
    throw Error(SourceLocation{path}, std::string("cannot read texture: ") + e.what());
  }
  if (IsJpeg(bytes)) {
    if (std::shared_ptr<TextureImage> jpeg = DecodeJpegAsFreeImage(bytes, path)) return jpeg;
  }
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                          static_cast<int>(bytes.size()), &width, &height, &channels, 4);
  if (!pixels) throw Error(SourceLocation{path}, std::string("cannot read texture: ") + stbi_failure_reason());
  auto texture = std::make_shared<TextureImage>();
  texture->width = width;
  texture->height = height;
  texture->channels = 4;
  texture->texels.assign(pixels, pixels + static_cast<size_t>(width) * height * 4);
  stbi_image_free(pixels);
  return texture;
}

}  // namespace

std::shared_ptr<const TextureImage> LoadTextureFile(const std::string& path) {
  std::error_code error;
  const std::string canonical = std::filesystem::canonical(path, error).string();
  if (error) throw Error(SourceLocation{path}, "cannot read texture: " + error.message());
  // keyed by the file's identity and version, so an edited file is read again
  const auto modified = std::filesystem::last_write_time(canonical, error).time_since_epoch().count();
  static SharedCache<std::pair<std::string, long long>, TextureImage> cache;
  return cache.Get({canonical, static_cast<long long>(modified)}, [&] { return Decode(canonical); });
}

std::shared_ptr<const TextureImage> WarningTexture() {
  static const std::shared_ptr<const TextureImage> warning = [] {
    auto texture = std::make_shared<TextureImage>();
    texture->width = texture->height = 8;
    texture->channels = 4;
    // texel (x, y) is black where (x + y) mod 8 < 4, else yellow (R5G6B5: exactly 255, 255, 0)
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        const std::uint8_t level = (x + y) % 8 < 4 ? 0 : 255;
        texture->texels.insert(texture->texels.end(), {level, level, 0, 255});
      }
    }
    return texture;
  }();
  return warning;
}

}  // namespace urdfsnap::texture
