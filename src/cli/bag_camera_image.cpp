// ReadBagCameraImage: ReadBagMessages on the one topic, each message's stamp decoded and the
// latest at or before the moment kept (its CDR bytes), then that one decoded into a picture.
#include "cli/bag_camera_image.h"

#include <optional>
#include <vector>

#include "bag/bag_messages.h"
#include "bag/cdr_message.h"
#include "bag/cdr_reader.h"
#include "camera/ros_image.h"
#include "common/error.h"

namespace urdfsnap::cli {
namespace {

constexpr const char* kImageType = "sensor_msgs/Image";
constexpr const char* kCompressedType = "sensor_msgs/CompressedImage";

// The message kept: the latest so far at or before the moment.
struct Latest {
  std::int64_t stamp_ns = 0;
  std::string where;
  std::vector<std::uint8_t> cdr;
};

image::Image Picture(const bag::MessageValue& m, bool compressed, const std::string& where) {
  if (compressed) return camera::ImageFromCompressed(m["format"].text, m["data"].bytes, where);
  return camera::ImageFromRos({static_cast<std::uint32_t>(m["width"].number),
                               static_cast<std::uint32_t>(m["height"].number), m["encoding"].text,
                               m["is_bigendian"].number != 0, static_cast<std::uint32_t>(m["step"].number),
                               m["data"].bytes},
                              where);
}

}  // namespace

BagCameraImage ReadBagCameraImage(const std::string& path, const std::string& topic, std::int64_t time_ns) {
  bool found = false, compressed = false;
  std::shared_ptr<const bag::MessageSchema> schema;
  std::optional<Latest> latest;
  const auto wanted = [&](const bag::BagTopic& t) {
    if (t.name != topic) return false;
    const std::string type = bag::ShortTypeName(t.type);
    if ((type != kImageType && type != kCompressedType) || t.encoding != "cdr") {
      throw Error(path + ": --underlay-topic '" + topic + "' carries '" + t.type + "' messages encoded as '" +
                  t.encoding + "'; urdfsnap reads sensor_msgs/msg/Image and CompressedImage in 'cdr' (ROS 2)");
    }
    found = true;
    compressed = type == kCompressedType;
    return true;
  };
  bag::ReadBagMessages(path, wanted, [&](const bag::BagMessage& message) {
    const std::string where = bag::DescribeMessage(message.file, message.topic.name, message.index, message.log_time);
    std::int64_t stamp = 0;
    try {
      const bag::MessageValue decoded = bag::DecodeMessage(*message.topic.schema, message.data);
      const bag::MessageValue& s = decoded["header"]["stamp"];
      stamp = static_cast<std::int64_t>(s["sec"].number) * 1'000'000'000 + static_cast<std::int64_t>(s["nanosec"].number);
    } catch (const bag::CdrError& e) {
      throw Error(where + ": not a " + message.topic.type + " in CDR: " + e.what());
    }
    if (stamp == 0) stamp = static_cast<std::int64_t>(message.log_time);
    if (stamp > time_ns || (latest && stamp < latest->stamp_ns)) return;
    latest = Latest{stamp, where, {message.data.begin(), message.data.end()}};
    schema = message.topic.schema;
  });
  if (!found) throw Error(path + ": no topic '" + topic + "' (--underlay-topic)");
  if (!latest) {
    throw Error(path + ": no image on '" + topic + "' at or before the moment drawn (stamp " +
                std::to_string(time_ns / 1'000'000'000) + "." + std::to_string(time_ns % 1'000'000'000 + 1'000'000'000).substr(1) +
                " s) (--underlay-topic)");
  }
  try {
    return {Picture(bag::DecodeMessage(*schema, latest->cdr), compressed, latest->where), latest->where};
  } catch (const bag::CdrError& e) {
    throw Error(latest->where + ": not an image message in CDR: " + e.what());
  }
}

}  // namespace urdfsnap::cli
