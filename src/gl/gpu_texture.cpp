// Upload of textures.
#include "gl/internal/gpu_texture.h"

#include "common/error.h"
#include "gl/internal/gl_api.h"

namespace urdfsnap::gl {

GpuTexture::GpuTexture(const texture::TextureImage& image) {
  if (image.channels != 2 && image.channels != 4) {
    throw Error("texture with " + std::to_string(image.channels) + " channels; expected 2 or 4");
  }
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const bool rg = image.channels == 2;
  glTexImage2D(GL_TEXTURE_2D, 0, rg ? GL_RG8 : GL_RGBA8, image.width, image.height, 0,
               rg ? GL_RG : GL_RGBA, GL_UNSIGNED_BYTE, image.texels.data());
  // Font::loadImpl: FO_LINEAR, FO_LINEAR, FO_NONE and TAM_CLAMP; TextureUnitState's defaults:
  // TFO_BILINEAR (nearest mip level) and TAM_WRAP, with mipmaps down to 1x1
  if (!rg) glGenerateMipmap(GL_TEXTURE_2D);
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
