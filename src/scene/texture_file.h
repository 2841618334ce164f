// Image files used as textures (URDF <texture>, the diffuse maps of mesh materials), decoded with
// stb_image into RGBA as Ogre's image codecs would hand them to RViz. GL-free.
#pragma once

#include <memory>
#include <string>

#include "scene/texture_image.h"

namespace urdfsnap::scene {

// Loads the image file at `path` (PNG, JPEG, BMP, TGA, GIF, PSD, PNM) as 4-channel RGBA, top row
// first. Each file is read once per process (keyed by its canonical path). Thread-safe. Throws
// urdfsnap::Error "PATH: ..." when the file is missing, not an image, or larger than
// image::kMaxImageSide on a side.
std::shared_ptr<const TextureImage> LoadTextureFile(const std::string& path);

}  // namespace urdfsnap::scene
