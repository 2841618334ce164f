// `render --bag FILE --at T --underlay-topic TOPIC`: the camera image a bag's topic shows at a
// moment, as RViz's Camera display shows the newest image it has: the latest message whose
// header stamp (its log time when the publisher left the stamp at zero) is at or before the
// moment. sensor_msgs/Image and sensor_msgs/CompressedImage (camera/ros_image.h).
#pragma once

#include <cstdint>
#include <string>

#include "image/image.h"

namespace urdfsnap::cli {

struct BagCameraImage {
  image::Image picture;
  std::string where;   // the message it came from (bag::DescribeMessage), for messages about it
};

// The image on `topic` of the bag at `path` at `time_ns` (nanoseconds since 1970). Only the latest
// message's data is kept while reading. Throws urdfsnap::Error naming the bag for a topic it does
// not have or whose type is neither image type, for no image at or before the moment, and naming
// the message for one that cannot be decoded or shown (camera::ImageFromRos).
BagCameraImage ReadBagCameraImage(const std::string& path, const std::string& topic, std::int64_t time_ns);

}  // namespace urdfsnap::cli
