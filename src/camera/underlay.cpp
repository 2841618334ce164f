// DrawnPixels and DrawUnderlay: per-pixel compositing of a camera image with the render.
#include "camera/underlay.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace urdfsnap::camera {
namespace {

// DrawnPixels' value where a display drew: beyond any link's label (at most 65534 links)
constexpr std::uint16_t kDisplayPixel = 0xFFFF;

}  // namespace

image::LabelImage DrawnPixels(const image::Frame& drawn, const Eigen::Vector3f& background) {
  image::LabelImage pixels = drawn.labels;
  std::uint8_t clear[3];
  for (int c = 0; c < 3; ++c) clear[c] = static_cast<std::uint8_t>(std::lround(std::clamp(background[c], 0.f, 1.f) * 255));
  const std::vector<std::uint8_t>& rgb = drawn.colour.rgb;
  for (size_t i = 0; i < pixels.labels.size(); ++i) {
    if (pixels.labels[i] == 0 && (rgb[i * 3] != clear[0] || rgb[i * 3 + 1] != clear[1] || rgb[i * 3 + 2] != clear[2])) {
      pixels.labels[i] = kDisplayPixel;
    }
  }
  return pixels;
}

void DrawUnderlay(const image::Image& underlay, const std::string& name, double alpha,
                  const image::LabelImage& drawn, image::Image& colour) {
  if (underlay.width != colour.width || underlay.height != colour.height) {
    throw Error(SourceLocation{name, 0}, "the underlay image is " + image::SizeText(underlay) +
                                             ", the camera's image " + image::SizeText(colour));
  }
  for (size_t i = 0; i < drawn.labels.size(); ++i) {
    for (size_t c = i * 3; c < i * 3 + 3; ++c) {
      colour.rgb[c] = drawn.labels[i] == 0
                          ? underlay.rgb[c]
                          : static_cast<std::uint8_t>(std::lround(alpha * underlay.rgb[c] + (1 - alpha) * colour.rgb[c]));
    }
  }
}

}  // namespace urdfsnap::camera
