// PNG decoding into RGB images, for golden-image tests and the compare command, and of 16-bit grey
// images (the depth and label goldens).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "image/image.h"

namespace urdfsnap::image {

// Reads the PNG file at `path` as 8-bit RGB, top row first: grey becomes three equal channels,
// alpha is dropped, 16-bit channels are reduced to 8. Throws urdfsnap::Error "PATH: ..." if the
// file cannot be read, is not a PNG, claims a width or height over kMaxImageSide (checked in the
// header before anything is decoded or allocated), or fails to decode.
Image ReadPng(const std::string& path);

// ReadPng for the bytes of a file already read; `path` names it in messages.
Image DecodePng(std::string_view bytes, const std::string& path);

// Reads a 16-bit greyscale PNG (depth in millimetres, link labels) with the same checks as ReadPng;
// an 8-bit file's values are scaled to 16 bits (x257) and colour is turned grey.
Gray16Image ReadGray16Png(const std::string& path);
Gray16Image DecodeGray16Png(std::string_view bytes, const std::string& path);

// The largest PNG file ReadPng reads: far more than the largest render (flat colours compress
// well), and a bound on what a pipe or device named as a PNG can make it hold in memory.
inline constexpr std::size_t kMaxPngFileBytes = std::size_t{512} << 20;

}  // namespace urdfsnap::image
