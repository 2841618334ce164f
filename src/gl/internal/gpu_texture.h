// A texture::TextureImage uploaded to the GPU: 2 channels as GL_RG8 (luminance in r, alpha in g), clamped
// and without mipmaps as Ogre's font textures; 4 as GL_RGBA8, repeated and mipmapped as Ogre's
// image textures (texture_image.h). Internal to the render library; needs a current GL context.
#pragma once

#include "texture/texture_image.h"

namespace urdfsnap::gl {

class GpuTexture {
 public:
  explicit GpuTexture(const texture::TextureImage& image);
  ~GpuTexture();
  GpuTexture(const GpuTexture&) = delete;
  GpuTexture& operator=(const GpuTexture&) = delete;

  // Binds the texture to texture unit `unit`.
  void Bind(int unit) const;

 private:
  unsigned id_ = 0;
};

}  // namespace urdfsnap::gl
