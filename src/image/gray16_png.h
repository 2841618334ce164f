// 16-bit greyscale PNG files (depth in millimetres, link labels), written with libpng: stb's PNG
// writer only has 8-bit channels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace urdfsnap::image {

// The PNG file bytes of a width x height image of 16-bit grey values (top row first). Throws
// urdfsnap::Error for a size outside 1..kMaxImageSide or a value count that does not match.
std::vector<std::uint8_t> EncodeGray16Png(int width, int height, const std::vector<std::uint16_t>& values);

// Encodes and writes to `path` atomically (see WriteFileAtomically).
void WriteGray16Png(int width, int height, const std::vector<std::uint16_t>& values, const std::string& path);

}  // namespace urdfsnap::image
