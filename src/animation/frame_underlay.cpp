// FrameUnderlay: the feed advanced to the frame's stamp, the display's picture set on the camera;
// the bag's topics read again only to say why nothing was shown.
#include "animation/frame_underlay.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "bag/topic_check.h"
#include "common/error.h"

namespace urdfsnap::animation {

FrameUnderlay::FrameUnderlay(std::string bag, std::string topic, double stamp_at_zero)
    : bag_(std::move(bag)), topic_(std::move(topic)), stamp_at_zero_(stamp_at_zero),
      image_(static_cast<display::CameraImageDisplay*>(
          &displays_.Add("camera image", std::make_unique<display::CameraImageDisplay>(topic_)))),
      feed_(bag_, displays_) {}

void FrameUnderlay::Attach(double t, render::CameraSettings& camera, Warnings& warnings) {
  const auto stamp = static_cast<std::int64_t>(std::llround((stamp_at_zero_ + t) * 1e9));
  // the feed's warnings (a topic of another type) are said by the error when nothing is shown
  Warnings fed;
  feed_.AdvanceTo(stamp, fed);
  const std::optional<display::CameraImageDisplay::Picture> shown = image_->Shown(stamp);
  if (!shown) {
    bag::RequireTopic({topic_, {"sensor_msgs/Image", "sensor_msgs/CompressedImage"}, "--underlay-topic",
                       "sensor_msgs/msg/Image and CompressedImage"},
                      bag_);
    throw Error(bag_ + ": no image on '" + topic_ + "' received at or before the moment drawn (stamp " +
                bag::TimeText(static_cast<std::uint64_t>(std::max<std::int64_t>(stamp, 0))) + " s) (--underlay-topic)");
  }
  for (const std::string& message : fed.messages()) warnings.Add(message);
  camera.underlay = shown->image;
  camera.underlay_file = shown->where;
}

}  // namespace urdfsnap::animation
