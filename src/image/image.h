// The pixel buffer every stage hands on: 8-bit RGB, rows from top to bottom (PNG order; GL's
// read-back is bottom-up, the render stage flips it).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace urdfsnap::image {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3 bytes, row after row, top row first
};

// The largest width and height urdfsnap encodes or decodes, in pixels: far above any render, and
// small enough that a crafted PNG header cannot make a reader allocate gigabytes.
inline constexpr int kMaxImageSide = 16384;

// Throws urdfsnap::Error naming `role` ("EncodePng", "expected image", ...) unless the image has a
// positive size within kMaxImageSide and rgb holds exactly width * height * 3 bytes.
void CheckImage(const Image& image, std::string_view role);

// "640x480".
std::string SizeText(const Image& image);

}  // namespace urdfsnap::image
