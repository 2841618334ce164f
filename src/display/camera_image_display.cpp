// CameraImageDisplay: each message's fields copied on receipt, the shown one decoded on demand by
// camera::ImageFromRos / ImageFromCompressed.
#include "display/camera_image_display.h"

#include <utility>

#include "bag/cdr_message.h"
#include "camera/ros_image.h"

namespace urdfsnap::display {

CameraImageDisplay::CameraImageDisplay(std::string topic) : topic_(std::move(topic)) {}

bool CameraImageDisplay::Reads(const std::string& type) const {
  return type == "sensor_msgs/msg/Image" || type == "sensor_msgs/Image" || type == "sensor_msgs/msg/CompressedImage" ||
         type == "sensor_msgs/CompressedImage";
}

void CameraImageDisplay::Receive(const bag::MessageValue& m, std::int64_t time_ns, const std::string& where,
                                 Warnings&) {
  Message message;
  const bag::MessageValue& stamp = m["header"]["stamp"];
  message.stamp_ns = LookupTime(
      static_cast<std::int64_t>(stamp["sec"].number) * 1'000'000'000 + static_cast<std::int64_t>(stamp["nanosec"].number),
      time_ns);
  message.where = where;
  message.data = m["data"].bytes;
  if (m.type != nullptr && m.type->name == "sensor_msgs/CompressedImage") {
    message.compressed = true;
    message.format = m["format"].text;
  } else {
    message.width = static_cast<std::uint32_t>(m["width"].number);
    message.height = static_cast<std::uint32_t>(m["height"].number);
    message.step = static_cast<std::uint32_t>(m["step"].number);
    message.encoding = m["encoding"].text;
    message.is_bigendian = m["is_bigendian"].number != 0;
  }
  if (message.stamp_ns <= time_ns) return Offer(std::move(message));
  waiting_.push_back(std::move(message));
  if (waiting_.size() > kWaiting) waiting_.pop_front();
}

void CameraImageDisplay::Offer(Message message) {
  if (shown_ && message.stamp_ns < shown_->stamp_ns) return;
  shown_ = std::move(message);
  picture_ = {};
}

std::optional<CameraImageDisplay::Picture> CameraImageDisplay::Shown(std::int64_t time_ns) {
  for (auto it = waiting_.begin(); it != waiting_.end();) {
    if (it->stamp_ns > time_ns) {
      ++it;
      continue;
    }
    Offer(std::move(*it));
    it = waiting_.erase(it);
  }
  if (!shown_) return std::nullopt;
  if (!picture_.image) {
    const Message& m = *shown_;
    picture_.where = m.where;
    picture_.image = std::make_shared<const image::Image>(
        m.compressed ? camera::ImageFromCompressed(m.format, m.data, m.where)
                     : camera::ImageFromRos({m.width, m.height, m.encoding, m.is_bigendian, m.step, m.data}, m.where));
  }
  return picture_;
}

}  // namespace urdfsnap::display
