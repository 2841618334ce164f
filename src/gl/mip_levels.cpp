// Mipmap levels of RGBA8 textures, texel for texel llvmpipe's (see internal/mip_levels.h).
#include "gl/internal/mip_levels.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace urdfsnap::gl {

namespace {

// The average of each of the four bytes of `a` and `b`, rounded up: (a + b + 1) / 2 per byte,
// without carries between them.
inline std::uint32_t AverageBytes(std::uint32_t a, std::uint32_t b) {
  return (a | b) - (((a ^ b) & 0xFEFEFEFEu) >> 1);
}

// The two texels of a side of `size` that llvmpipe blends for texel `i` of the level below.
inline void SourcePair(int size, int i, int& first, int& second) {
  if (size == 1) {
    first = second = 0;
  } else if (size == 3) {
    first = second = 1;
  } else {
    first = 2 * i;
    second = 2 * i + 1;
  }
}

}  // namespace

bool MipLevelsExact(int width, int height) {
  if (width < 1 || height < 1) return false;
  const auto exact = [](int side) { return side == 1 || side == 3 || side % 2 == 0; };
  for (; width > 1 || height > 1; width = std::max(1, width / 2), height = std::max(1, height / 2)) {
    if (!exact(width) || !exact(height)) return false;
  }
  return true;
}

int MipLevelCount(int width, int height) {
  return std::bit_width(static_cast<unsigned>(std::max({width, height, 1})));
}

std::vector<std::uint8_t> NextMipLevel(const std::vector<std::uint8_t>& texels, int width, int height) {
  const int next_width = std::max(1, width / 2), next_height = std::max(1, height / 2);
  std::vector<std::uint8_t> next(static_cast<size_t>(next_width) * next_height * 4);
  const auto texel = [&](int x, int y) {
    std::uint32_t value;
    std::memcpy(&value, texels.data() + (static_cast<size_t>(y) * width + x) * 4, 4);
    return value;
  };
  for (int y = 0; y < next_height; ++y) {
    int y0, y1;
    SourcePair(height, y, y0, y1);
    std::uint8_t* row = next.data() + static_cast<size_t>(y) * next_width * 4;
    for (int x = 0; x < next_width; ++x) {
      int x0, x1;
      SourcePair(width, x, x0, x1);
      const std::uint32_t value =
          AverageBytes(AverageBytes(texel(x0, y0), texel(x1, y0)), AverageBytes(texel(x0, y1), texel(x1, y1)));
      std::memcpy(row + static_cast<size_t>(x) * 4, &value, 4);
    }
  }
  return next;
}

}  // namespace urdfsnap::gl
