// Upload of textures, with their mipmap levels made on the CPU where they match llvmpipe's.
#include "gl/internal/gpu_texture.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/error.h"
#include "gl/internal/gl_api.h"
#include "gl/internal/mip_levels.h"

namespace urdfsnap::gl {

namespace {

// Uploads RGBA `image` into the bound texture with every mipmap level, made here as llvmpipe's
// glGenerateMipmap would make them (MipLevelsExact of its size must hold), in storage allocated
// once for all of them.
void UploadWithMipLevels(const texture::TextureImage& image) {
  int width = image.width, height = image.height;
  glTexStorage2D(GL_TEXTURE_2D, MipLevelCount(width, height), GL_RGBA8, width, height);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.texels.data());
  std::vector<std::uint8_t> level;
  for (int index = 1; width > 1 || height > 1; ++index) {
    level = NextMipLevel(index == 1 ? image.texels : level, width, height);
    width = std::max(1, width / 2);
    height = std::max(1, height / 2);
    glTexSubImage2D(GL_TEXTURE_2D, index, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, level.data());
  }
}

}  // namespace

GpuTexture::GpuTexture(const texture::TextureImage& image) {
  if (image.channels != 2 && image.channels != 4) {
    throw Error("texture with " + std::to_string(image.channels) + " channels; expected 2 or 4");
  }
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const bool rg = image.channels == 2;
  // Font::loadImpl: FO_LINEAR, FO_LINEAR, FO_NONE and TAM_CLAMP; TextureUnitState's defaults:
  // TFO_BILINEAR (nearest mip level) and TAM_WRAP, with mipmaps down to 1x1
  if (!rg && MipLevelsExact(image.width, image.height)) {
    UploadWithMipLevels(image);
  } else {
    glTexImage2D(GL_TEXTURE_2D, 0, rg ? GL_RG8 : GL_RGBA8, image.width, image.height, 0,
                 rg ? GL_RG : GL_RGBA, GL_UNSIGNED_BYTE, image.texels.data());
    if (!rg) glGenerateMipmap(GL_TEXTURE_2D);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, rg ? GL_LINEAR : GL_LINEAR_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, rg ? GL_CLAMP_TO_EDGE : GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, rg ? GL_CLAMP_TO_EDGE : GL_REPEAT);
}

GpuTexture::~GpuTexture() { glDeleteTextures(1, &id_); }

void GpuTexture::Bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, id_);
}

}  // namespace urdfsnap::gl
