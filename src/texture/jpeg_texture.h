// JPEG textures decoded as RViz gets them. RViz's Ogre reads images through its FreeImage codec,
// and FreeImage's default load flags make libjpeg use its fast integer IDCT (JDCT_IFAST) and no
// "fancy" (interpolating) chroma upsampling. Other decoders differ: stb_image decodes the Atlas
// robot's 2048x2048 texture with 20% of the values 2 or more levels off, 0.74 brighter on
// average. GL-free.
#pragma once

#include <memory>
#include <string_view>

#include "texture/texture_image.h"

namespace urdfsnap::texture {

// True when `bytes` start as a JPEG file does (the SOI marker and another marker).
bool IsJpeg(std::string_view bytes);

// Decodes the JPEG file `bytes` to 4-channel RGBA (alpha 255), top row first, with libjpeg set up
// as FreeImage sets it up by default. Returns null for CMYK and YCCK images, which FreeImage
// converts by rules of its own (leave those to another decoder). Throws urdfsnap::Error
// "PATH: cannot read texture: ..." with libjpeg's reason for a corrupt file, and for an image
// larger than image::kMaxImageSide on a side.
std::shared_ptr<TextureImage> DecodeJpegAsFreeImage(std::string_view bytes, const std::string& path);

}  // namespace urdfsnap::texture
