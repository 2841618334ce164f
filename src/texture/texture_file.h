// Image files used as textures (URDF <texture>, the diffuse maps of mesh materials), decoded into
// RGBA as Ogre's FreeImage codec hands them to RViz: JPEG through libjpeg with FreeImage's
// settings (jpeg_texture.h), the rest with stb_image (lossless formats decode alike). GL-free.
#pragma once

#include <memory>
#include <string>

#include "texture/texture_image.h"

namespace urdfsnap::texture {

// Loads the image file at `path` (PNG, JPEG, BMP, TGA, GIF, PSD, PNM) as 4-channel RGBA, top row
// first. While the returned image is held anywhere, later calls naming the same unchanged file
// return it (common/shared_cache.h). Thread-safe. Throws
// urdfsnap::Error "PATH: ..." when the file is missing, larger than 1 GiB, not an image, or
// larger than image::kMaxImageSide on a side.
std::shared_ptr<const TextureImage> LoadTextureFile(const std::string& path);

// Ogre's warning texture (TextureManager::_getWarningTexture, Ogre 1.12): 8x8 texels of diagonal
// yellow and black stripes, which Ogre binds to a texture unit whose image cannot be loaded. RViz
// shows it for a missing texture file, and for a mesh material with texture maps but no diffuse
// map. The same object on every call.
std::shared_ptr<const TextureImage> WarningTexture();

}  // namespace urdfsnap::texture
