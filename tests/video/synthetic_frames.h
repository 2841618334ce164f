// Frames with the structure of a robot animation, for the encoder tests and benchmarks: RViz's
// grey background, a perspective grid of thin lines, a shaded red disc that moves and a blue bar
// that turns from frame to frame, a strip of every hue (a palette's hardest case), and the frame's
// number in binary as eight squares across the top (so that any two neighbouring frames differ in
// at least a sixty-fourth of the picture). Black or constant frames would pass a broken encoder;
// these do not.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "image/image.h"

namespace urdfsnap::test {

inline image::Image SyntheticFrame(int width, int height, int index) {
  image::Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3, 48)};
  const auto put = [&](int x, int y, double r, double g, double b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    std::uint8_t* p = &image.rgb[3 * (std::size_t(y) * width + x)];
    p[0] = static_cast<std::uint8_t>(std::clamp(r, 0.0, 255.0));
    p[1] = static_cast<std::uint8_t>(std::clamp(g, 0.0, 255.0));
    p[2] = static_cast<std::uint8_t>(std::clamp(b, 0.0, 255.0));
  };
  // grid: lines converging above the image, and horizontal lines
  for (int i = -6; i <= 6; ++i) {
    for (int y = height * 2 / 5; y < height; ++y) {
      put(static_cast<int>(width / 2 + i * (y - height / 4) * 0.45), y, 160, 160, 164);
    }
    const int y = height * 3 / 5 + i * height / 40 + i * i;
    for (int x = width / 16; x < width * 15 / 16; ++x) put(x, y, 160, 160, 164);
  }
  // a shaded disc moving left to right
  const double cx = width * (0.15 + 0.7 * std::fmod(index * 0.061, 1.0)), cy = height * 0.45;
  const double radius = height * 0.18;
  for (int y = static_cast<int>(cy - radius); y <= cy + radius; ++y) {
    for (int x = static_cast<int>(cx - radius); x <= cx + radius; ++x) {
      const double dx = (x - cx) / radius, dy = (y - cy) / radius;
      if (dx * dx + dy * dy > 1) continue;
      const double shade = std::sqrt(1 - dx * dx - dy * dy) * 0.7 + 0.3 * (0.5 - 0.5 * dx);
      put(x, y, 60 + 190 * shade, 25 * shade, 20 * shade);
    }
  }
  // a blue bar turning about a point
  const double angle = index * 0.1;
  for (double t = 0; t < height * 0.35; t += 0.5) {
    for (double s = -6; s <= 6; s += 0.5) {
      put(static_cast<int>(width * 0.75 + t * std::cos(angle) - s * std::sin(angle)),
          static_cast<int>(height * 0.35 + t * std::sin(angle) + s * std::cos(angle)), 30, 80,
          200 + s * 5);
    }
  }
  // every hue along the bottom
  for (int y = height - height / 12; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double hue = 6.0 * x / width;
      const auto channel = [&](double offset) {
        const double d = std::fmod(hue + offset, 6.0);
        return 255 * std::clamp(std::abs(d - 3) - 1, 0.0, 1.0);
      };
      put(x, y, channel(0), channel(4), channel(2));
    }
  }
  // the frame number, bit by bit from the left: light squares for ones, dark for zeros
  const int side = height / 8;
  for (int bit = 0; bit < 8; ++bit) {
    const double value = (index >> (7 - bit)) & 1 ? 230 : 16;
    for (int y = 0; y < side; ++y) {
      for (int x = bit * side; x < (bit + 1) * side; ++x) put(x, y, value, value, value);
    }
  }
  return image;
}

}  // namespace urdfsnap::test
