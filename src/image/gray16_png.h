// 16-bit greyscale PNG files (depth in millimetres, link labels): stb's PNG writer only has 8-bit
// channels, so the few PNG chunks are framed here around libdeflate's zlib stream.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace urdfsnap::image {

// The PNG file bytes of `image` (16-bit grey, top row first). Throws urdfsnap::Error for a size
// outside 1..kMaxImageSide or a value count that does not match it.
std::vector<std::uint8_t> EncodeGray16Png(const Gray16Image& image);

// Encodes and writes to `path` atomically (see WriteFileAtomically).
void WriteGray16Png(const Gray16Image& image, const std::string& path);

}  // namespace urdfsnap::image
