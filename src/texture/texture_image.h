// A GL-free texture: 8-bit texels as RViz's Ogre would upload them, top row first (Ogre's v = 0 is
// the image's top row, and GL's t = 0 is the first row uploaded, so no flip is needed anywhere).
#pragma once

#include <cstdint>
#include <vector>

namespace urdfsnap::texture {

struct TextureImage {
  int width = 0;
  int height = 0;
  // 2: luminance and alpha (Ogre's PF_BYTE_LA, the font texture), sampled as Ogre's Font sets it up:
  // clamped, no mipmaps; 4: RGBA (image files), sampled as Ogre's defaults: repeated, mipmapped,
  // bilinear within the nearest mip level (TFO_BILINEAR)
  int channels = 4;
  std::vector<std::uint8_t> texels;   // width * height * channels bytes, row after row
};

}  // namespace urdfsnap::texture
