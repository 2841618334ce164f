// RViz's Camera display's image, received from a bag as time moves forward: the picture shown
// behind a calibrated camera's robot (render::CameraSettings::underlay) at each moment. As RViz
// shows the newest image it has received whose stamp TF can reach, the image at time T is, of the
// messages received (logged) at or before T, the one with the latest header stamp at or before T
// (the log time for a stamp of 0; of equal stamps the one received last). A message stamped after
// the moment it was received waits until the moment reaches its stamp; at most kWaiting wait, the
// oldest dropped first. Memory holds the shown message and the waiting ones (their bytes, not
// decoded), and the shown picture decoded once; nothing else of the topic.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "display/display.h"
#include "image/image.h"

namespace urdfsnap::display {

class CameraImageDisplay : public Display {
 public:
  // Messages that may wait for their stamp at once.
  static constexpr std::size_t kWaiting = 5;

  explicit CameraImageDisplay(std::string topic);

  const std::string& topic() const override { return topic_; }
  // sensor_msgs Image and CompressedImage
  bool Reads(const std::string& type) const override;
  void Receive(const bag::MessageValue& message, std::int64_t time_ns, const std::string& where,
               Warnings& warnings) override;
  // Draws nothing into the scene: the camera shows the picture (Shown).
  void Draw(std::int64_t, const FrameLookup&, scene::Scene&, Warnings&) const override {}

  // The picture shown at `time_ns` (the displays fed up to it; never earlier than a previous
  // call's), and the message it came from; nothing when no image has been received by then.
  // Throws urdfsnap::Error naming the message for one that cannot be shown (camera/ros_image.h).
  struct Picture {
    std::shared_ptr<const image::Image> image;
    std::string where;
  };
  std::optional<Picture> Shown(std::int64_t time_ns);

 private:
  // A received message's fields, its bytes copied out of the bag's buffer.
  struct Message {
    std::int64_t stamp_ns = 0;
    std::string where;
    bool compressed = false;
    std::string format;   // CompressedImage
    std::uint32_t width = 0, height = 0, step = 0;   // Image
    std::string encoding;
    bool is_bigendian = false;
    std::vector<std::uint8_t> data;
  };
  // Makes `message` the shown one when its stamp is not older than the shown one's.
  void Offer(Message message);

  std::string topic_;
  std::optional<Message> shown_;
  std::deque<Message> waiting_;   // in the order received
  Picture picture_;               // shown_ decoded, once asked for
};

}  // namespace urdfsnap::display
