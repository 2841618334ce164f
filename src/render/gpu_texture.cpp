// Upload of textures.
#include "render/gpu_texture.h"

#include "common/error.h"
#include "render/gl_api.h"

namespace urdfsnap::render {

GpuTexture::GpuTexture(const TextureImage& image) {
  if (image.channels != 2 && image.channels != 4) {
    throw Error("texture with " + std::to_string(image.channels) + " channels; expected 2 or 4");
  }
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const bool rg = image.channels == 2;
  glTexImage2D(GL_TEXTURE_2D, 0, rg ? GL_RG8 : GL_RGBA8, image.width, image.height, 0,
               rg ? GL_RG : GL_RGBA, GL_UNSIGNED_BYTE, image.texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GpuTexture::~GpuTexture() { glDeleteTextures(1, &id_); }

void GpuTexture::Bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, id_);
}

}  // namespace urdfsnap::render
