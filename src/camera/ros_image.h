// A camera image as ROS carries it (sensor_msgs/Image, sensor_msgs/CompressedImage) made into the
// 8-bit RGB picture RViz's Camera display shows (rviz_default_plugins' ROSImageTexture): rgb8,
// bgr8, rgba8, bgra8 (and 8UC3, 8UC4 as BGR) shown as they are, alpha dropped; mono8 (8UC1) as
// grey; mono16, 16UC1 and 32FC1 (depth) as grey scaled from the image's smallest value (black) to
// its largest (white), as ROSImageTexture's default "normalize" does; compressed images as JPEG or
// PNG. GL-free, bag-free: the message's fields in, an image out.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "image/image.h"

namespace urdfsnap::camera {

// The fields of a sensor_msgs/Image.
struct RosImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::string encoding;        // "rgb8", "mono16", "32FC1", ...
  bool is_bigendian = false;   // of 16- and 32-bit samples
  std::uint32_t step = 0;      // bytes per row, padding included
  std::span<const std::uint8_t> data;
};

// The picture of `message`. Throws urdfsnap::Error naming `where` (the message) for an encoding
// RViz does not show, a size outside 1x1 to kMaxImageSide, a step shorter than a row, or data
// shorter than step x height: nothing is read past the data.
image::Image ImageFromRos(const RosImage& message, const std::string& where);

// The picture of a sensor_msgs/CompressedImage's data (format "jpeg", "png", or image_transport's
// "rgb8; jpeg compressed bgr8"): decoded by its content, JPEG or PNG. Throws urdfsnap::Error naming
// `where` for anything else and for data that does not decode.
image::Image ImageFromCompressed(std::string_view format, std::span<const std::uint8_t> data,
                                 const std::string& where);

}  // namespace urdfsnap::camera
