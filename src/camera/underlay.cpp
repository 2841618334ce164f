// DrawUnderlay: per-pixel compositing of a camera image with the robot's render.
#include "camera/underlay.h"

#include <cmath>

#include "common/error.h"

namespace urdfsnap::camera {

void DrawUnderlay(const image::Image& underlay, const std::string& name, double alpha,
                  const image::LabelImage& robot, image::Image& colour) {
  if (underlay.width != colour.width || underlay.height != colour.height) {
    throw Error(SourceLocation{name, 0}, "the underlay image is " + image::SizeText(underlay) +
                                             ", the camera's image " + image::SizeText(colour));
  }
  for (size_t i = 0; i < robot.labels.size(); ++i) {
    for (size_t c = i * 3; c < i * 3 + 3; ++c) {
      colour.rgb[c] = robot.labels[i] == 0
                          ? underlay.rgb[c]
                          : static_cast<std::uint8_t>(std::lround(alpha * underlay.rgb[c] + (1 - alpha) * colour.rgb[c]));
    }
  }
}

}  // namespace urdfsnap::camera
