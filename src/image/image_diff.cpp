// Per-pixel comparison of two equally sized RGB images and the magenta/yellow-on-grey diff picture.
#include "image/image_diff.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/error.h"

namespace urdfsnap::image {
namespace {

void CheckComparable(const Image& expected, const Image& actual) {
  CheckImage(expected, "expected image");
  CheckImage(actual, "actual image");
  if (expected.width != actual.width || expected.height != actual.height) {
    throw Error("image sizes differ: expected " + SizeText(expected) + ", actual " +
                SizeText(actual));
  }
}

// The largest channel difference of pixel `i` (0..255).
int PixelDelta(const Image& a, const Image& b, std::size_t i) {
  int delta = 0;
  for (std::size_t c = 3 * i; c < 3 * i + 3; ++c)
    delta = std::max(delta, std::abs(a.rgb[c] - b.rgb[c]));
  return delta;
}

}  // namespace

DiffStats CompareImages(const Image& expected, const Image& actual, int delta) {
  CheckComparable(expected, actual);
  DiffStats stats;
  long long delta_sum = 0;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const int d = PixelDelta(expected, actual, std::size_t(y) * expected.width + x);
      delta_sum += d;
      stats.max_delta = std::max(stats.max_delta, d);
      if (d <= delta) continue;
      ++stats.pixels_over;
      GrowRegion(stats, x, y);
    }
  }
  const double pixel_count = double(expected.width) * expected.height;
  stats.mean_delta = delta_sum / pixel_count;
  stats.fraction_over = stats.pixels_over / pixel_count;
  return stats;
}

std::uint8_t DimmedGrey(const std::uint8_t* rgb) {
  // Rec. 601 luma in 0..255, squeezed into 64..127 so that no grey comes near magenta or yellow
  const int luma = (77 * rgb[0] + 150 * rgb[1] + 29 * rgb[2]) >> 8;
  return static_cast<std::uint8_t>(64 + luma / 4);
}

bool WithinTolerance(const DiffStats& stats, const DiffTolerance& tolerance) {
  return stats.fraction_over <= tolerance.max_fraction && stats.mean_delta <= tolerance.max_mean;
}

std::string DescribeDiff(const DiffStats& stats, const DiffTolerance& tolerance) {
  char text[256];
  std::snprintf(text, sizeof text,
                "max delta %d, mean delta %.3f (limit %g), %d pixels (%.3f%%) over %d (limit %g%%)",
                stats.max_delta, stats.mean_delta, tolerance.max_mean, stats.pixels_over,
                100 * stats.fraction_over, tolerance.max_delta, 100 * tolerance.max_fraction);
  std::string line = text;
  if (stats.pixels_over > 0) {
    std::snprintf(text, sizeof text, ", in x %d..%d, y %d..%d", stats.min_x, stats.max_x,
                  stats.min_y, stats.max_y);
    line += text;
  }
  return line;
}

Image MakeDiffImage(const Image& expected, const Image& actual, int delta) {
  CheckComparable(expected, actual);
  Image diff{expected.width, expected.height, std::vector<std::uint8_t>(expected.rgb.size())};
  for (std::size_t i = 0; i < diff.rgb.size() / 3; ++i) {
    std::uint8_t* out = &diff.rgb[3 * i];
    const int pixel_delta = PixelDelta(expected, actual, i);
    if (pixel_delta > delta) {
      out[0] = 255, out[1] = 0, out[2] = 255;
      continue;
    }
    if (pixel_delta > 0) {
      out[0] = 255, out[1] = 200, out[2] = 0;
      continue;
    }
    std::fill_n(out, 3, DimmedGrey(&expected.rgb[3 * i]));
  }
  return diff;
}

}  // namespace urdfsnap::image
