// Per-pixel comparison of two 16-bit images (depth in mm, link labels), their viewable pictures and
// the diff picture.
#include "image/gray16_diff.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/error.h"
#include "image/image_diff.h"

namespace urdfsnap::image {
namespace {

void CheckGray16(const Gray16Image& image, const char* role) {
  CheckImageSize(image.width, image.height, role);
  const std::size_t expected = std::size_t(image.width) * std::size_t(image.height);
  if (image.values.size() != expected) {
    throw Error(std::string(role) + ": a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " 16-bit image needs " + std::to_string(expected) + " values, got " +
                std::to_string(image.values.size()));
  }
}

std::string Gray16SizeText(const Gray16Image& image) { return SizeText(image.width, image.height); }

void CheckComparable(const Gray16Image& expected, const Gray16Image& actual) {
  CheckGray16(expected, "expected image");
  CheckGray16(actual, "actual image");
  if (expected.width != actual.width || expected.height != actual.height) {
    throw Error("image sizes differ: expected " + Gray16SizeText(expected) + ", actual " +
                Gray16SizeText(actual));
  }
}

// How pixel values compare, once per pixel.
enum class PixelVerdict { kSame, kWithin, kOver, kCoverage };

PixelVerdict Judge(int expected, int actual, int max_delta) {
  if (expected == actual) return PixelVerdict::kSame;
  if ((expected == 0) != (actual == 0)) return PixelVerdict::kCoverage;
  return std::abs(expected - actual) > max_delta ? PixelVerdict::kOver : PixelVerdict::kWithin;
}

Image Blank(int width, int height) {
  return Image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
}

void Put(std::uint8_t* out, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  out[0] = r, out[1] = g, out[2] = b;
}

}  // namespace

Gray16Tolerance DefaultTolerance(Gray16Kind kind) {
  if (kind == Gray16Kind::kLabels) return Gray16Tolerance{0, 0};
  return Gray16Tolerance{2, 0.0001};
}

Gray16DiffStats CompareGray16(const Gray16Image& expected, const Gray16Image& actual, Gray16Kind kind,
                              int max_delta) {
  CheckComparable(expected, actual);
  if (kind == Gray16Kind::kLabels && max_delta != 0) throw Error("labels are compared exactly (max delta 0)");
  Gray16DiffStats stats;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const std::size_t i = std::size_t(y) * expected.width + x;
      const int a = expected.values[i], b = actual.values[i];
      const PixelVerdict verdict = Judge(a, b, max_delta);
      if (kind == Gray16Kind::kDepth && a != 0 && b != 0) stats.max_delta = std::max(stats.max_delta, std::abs(a - b));
      if (verdict == PixelVerdict::kSame || verdict == PixelVerdict::kWithin) continue;
      ++stats.pixels_over;
      stats.pixels_coverage += verdict == PixelVerdict::kCoverage;
      GrowRegion(stats, x, y);
    }
  }
  stats.fraction_over = stats.pixels_over / (double(expected.width) * expected.height);
  return stats;
}

bool WithinTolerance(const Gray16DiffStats& stats, const Gray16Tolerance& tolerance) {
  return stats.fraction_over <= tolerance.max_fraction;
}

std::string DescribeGray16Diff(const Gray16DiffStats& stats, const Gray16Tolerance& tolerance, Gray16Kind kind) {
  char text[256];
  if (kind == Gray16Kind::kDepth) {
    std::snprintf(text, sizeof text, "max delta %d mm, %d pixels (%.3f%%) over %d mm (limit %g%%)",
                  stats.max_delta, stats.pixels_over, 100 * stats.fraction_over, tolerance.max_delta,
                  100 * tolerance.max_fraction);
  } else {
    std::snprintf(text, sizeof text, "%d pixels (%.3f%%) differ (limit %g%%)", stats.pixels_over,
                  100 * stats.fraction_over, 100 * tolerance.max_fraction);
  }
  std::string line = text;
  if (stats.pixels_coverage > 0) {
    line += ", " + std::to_string(stats.pixels_coverage) + " of them robot in one image only";
  }
  if (stats.pixels_over > 0) {
    std::snprintf(text, sizeof text, ", in x %d..%d, y %d..%d", stats.min_x, stats.max_x, stats.min_y, stats.max_y);
    line += text;
  }
  return line;
}

void Gray16ValueRange(const Gray16Image& a, const Gray16Image& b, int& low, int& high) {
  low = 65536, high = 0;
  for (const Gray16Image* image : {&a, &b}) {
    for (const std::uint16_t value : image->values) {
      if (value == 0) continue;
      low = std::min(low, int(value));
      high = std::max(high, int(value));
    }
  }
  if (high == 0) low = high = 1;
}

Image DepthPicture(const Gray16Image& depth, int near_mm, int far_mm) {
  CheckGray16(depth, "depth image");
  // viridis's colours, reversed: near is bright yellow, far dark purple (readable on black)
  static constexpr std::array<std::array<double, 3>, 5> kStops = {{
      {253, 231, 37}, {94, 201, 98}, {33, 145, 140}, {59, 82, 139}, {68, 1, 84}}};
  Image picture = Blank(depth.width, depth.height);
  const double span = std::max(far_mm - near_mm, 1);
  for (std::size_t i = 0; i < depth.values.size(); ++i) {
    if (depth.values[i] == 0) continue;
    const double t = std::clamp((depth.values[i] - near_mm) / span, 0.0, 1.0) * (kStops.size() - 1);
    const std::size_t stop = std::min(static_cast<std::size_t>(t), kStops.size() - 2);
    const double f = t - stop;
    for (int c = 0; c < 3; ++c) {
      picture.rgb[3 * i + c] = static_cast<std::uint8_t>(std::lround(kStops[stop][c] * (1 - f) + kStops[stop + 1][c] * f));
    }
  }
  return picture;
}

Image LabelPicture(const Gray16Image& labels) {
  CheckGray16(labels, "label image");
  Image picture = Blank(labels.width, labels.height);
  for (std::size_t i = 0; i < labels.values.size(); ++i) {
    const int label = labels.values[i];
    if (label == 0) continue;
    // hues a golden angle apart: neighbouring links (parent and child) never look alike
    const double hue = std::fmod(label * 0.618033988749895, 1.0) * 6;
    const int sector = static_cast<int>(hue);
    const double f = hue - sector;
    const double v = 240, p = v * 0.25, q = v * (1 - 0.75 * f), t = v * (1 - 0.75 * (1 - f));
    const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    for (int c = 0; c < 3; ++c) picture.rgb[3 * i + c] = static_cast<std::uint8_t>(std::lround(rgb[sector][c]));
  }
  return picture;
}

Image MakeGray16DiffImage(const Gray16Image& expected, const Gray16Image& actual, int max_delta,
                          const Image& expected_picture) {
  CheckComparable(expected, actual);
  CheckImage(expected_picture, "expected picture");
  if (expected_picture.width != expected.width || expected_picture.height != expected.height) {
    throw Error("the expected picture is " + SizeText(expected_picture) + ", the images " + Gray16SizeText(expected));
  }
  Image diff = Blank(expected.width, expected.height);
  for (std::size_t i = 0; i < expected.values.size(); ++i) {
    std::uint8_t* out = &diff.rgb[3 * i];
    switch (Judge(expected.values[i], actual.values[i], max_delta)) {
      case PixelVerdict::kOver: Put(out, 255, 0, 255); break;
      case PixelVerdict::kCoverage: Put(out, 0, 255, 255); break;
      case PixelVerdict::kWithin: Put(out, 255, 200, 0); break;
      case PixelVerdict::kSame: std::fill_n(out, 3, DimmedGrey(&expected_picture.rgb[3 * i])); break;
    }
  }
  return diff;
}

}  // namespace urdfsnap::image
