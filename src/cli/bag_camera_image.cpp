// LatestMessage: ReadBagMessages on the one topic, each message's stamp decoded and the latest at
// or before the moment kept (its CDR bytes), then that one decoded; the image and the calibration
// read from it.
#include "cli/bag_camera_image.h"

#include <algorithm>
#include <memory>
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
constexpr const char* kCameraInfoType = "sensor_msgs/CameraInfo";

// The message shown at a moment, decoded (its definition kept alive: the value points into it),
// with its type (short: "sensor_msgs/Image") and place.
struct Latest {
  std::shared_ptr<const bag::MessageSchema> schema;
  bag::MessageValue message;
  std::string type, where;
};

// "1700000000.500000000"
std::string StampText(std::int64_t time_ns) {
  return std::to_string(time_ns / 1'000'000'000) + "." +
         std::to_string(time_ns % 1'000'000'000 + 1'000'000'000).substr(1);
}

// The latest message on `topic` at or before `time_ns`, whose type must be one of `types` (what
// `option`, which names the topic, reads).
Latest LatestMessage(const std::string& path, const std::string& topic, std::int64_t time_ns,
                     std::initializer_list<const char*> types, const std::string& option, const std::string& what) {
  struct Kept {
    std::int64_t stamp_ns = 0;
    std::string where;
    std::vector<std::uint8_t> cdr;
  };
  std::optional<Kept> kept;
  std::shared_ptr<const bag::MessageSchema> schema;
  std::string type;
  const auto wanted = [&](const bag::BagTopic& t) {
    if (t.name != topic) return false;
    type = bag::ShortTypeName(t.type);
    if (std::find(types.begin(), types.end(), type) == types.end() || t.encoding != "cdr") {
      throw Error(path + ": " + option + " '" + topic + "' carries '" + t.type + "' messages encoded as '" +
                  t.encoding + "'; urdfsnap reads " + what + " in 'cdr' (ROS 2)");
    }
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
    if (stamp > time_ns || (kept && stamp < kept->stamp_ns)) return;
    kept = Kept{stamp, where, {message.data.begin(), message.data.end()}};
    schema = message.topic.schema;
  });
  if (type.empty()) throw Error(path + ": no topic '" + topic + "' (" + option + ")");
  if (!kept) {
    throw Error(path + ": no message on '" + topic + "' at or before the moment drawn (stamp " + StampText(time_ns) +
                " s) (" + option + ")");
  }
  try {
    return {schema, bag::DecodeMessage(*schema, kept->cdr), type, kept->where};
  } catch (const bag::CdrError& e) {
    throw Error(kept->where + ": not a " + type + " in CDR: " + e.what());
  }
}

// Numbers of a float64 array field.
std::vector<double> Numbers(const bag::MessageValue& array) {
  std::vector<double> numbers;
  for (const bag::MessageValue& item : array.items) numbers.push_back(item.number);
  return numbers;
}

}  // namespace

BagCameraImage ReadBagCameraImage(const std::string& path, const std::string& topic, std::int64_t time_ns) {
  const Latest latest = LatestMessage(path, topic, time_ns, {kImageType, kCompressedType}, "--underlay-topic",
                                      "sensor_msgs/msg/Image and CompressedImage");
  const bag::MessageValue& m = latest.message;
  if (latest.type == kCompressedType) {
    return {camera::ImageFromCompressed(m["format"].text, m["data"].bytes, latest.where), latest.where};
  }
  return {camera::ImageFromRos({static_cast<std::uint32_t>(m["width"].number),
                                static_cast<std::uint32_t>(m["height"].number), m["encoding"].text,
                                m["is_bigendian"].number != 0, static_cast<std::uint32_t>(m["step"].number),
                                m["data"].bytes},
                               latest.where),
          latest.where};
}

camera::CameraInfo ReadBagCameraInfo(const std::string& path, const std::string& topic, std::int64_t time_ns) {
  const Latest latest =
      LatestMessage(path, topic, time_ns, {kCameraInfoType}, "--camera-info-topic", "sensor_msgs/msg/CameraInfo");
  const bag::MessageValue& m = latest.message;
  camera::CameraInfo info;
  info.width = static_cast<int>(std::min(m["width"].number, 1e9));
  info.height = static_cast<int>(std::min(m["height"].number, 1e9));
  info.distortion_model = m["distortion_model"].text;
  info.D = Numbers(m["d"]);
  const std::vector<double> k = Numbers(m["k"]), r = Numbers(m["r"]), p = Numbers(m["p"]);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) info.K(row, col) = k[3 * row + col], info.R(row, col) = r[3 * row + col];
    for (int col = 0; col < 4; ++col) info.P(row, col) = p[4 * row + col];
  }
  info.frame_id = m["header"]["frame_id"].text;
  camera::CheckCameraInfoMessage(info, latest.where);
  return info;
}

}  // namespace urdfsnap::cli
