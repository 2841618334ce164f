// `render --bag FILE --at T` with a camera from the recording: --underlay-topic's image and
// --camera-info-topic's calibration, each the topic's message RViz's Camera display would show at
// the moment: the latest whose header stamp (its log time when the publisher left the stamp at
// zero) is at or before it. Images are sensor_msgs/Image or CompressedImage (camera/ros_image.h).
#pragma once

#include <cstdint>
#include <string>

#include "camera/camera_info.h"
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

// The sensor_msgs/CameraInfo on `topic` at `time_ns`, checked as a --camera-info file is. Throws
// as ReadBagCameraImage does, and naming the message for a calibration that is not usable.
camera::CameraInfo ReadBagCameraInfo(const std::string& path, const std::string& topic, std::int64_t time_ns);

}  // namespace urdfsnap::cli
