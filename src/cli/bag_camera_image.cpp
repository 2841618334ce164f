// ReadBagCameraInfo: ReadBagMessages on the one topic, each message's stamp decoded and the latest
// at or before the moment kept (its CDR bytes), then that one decoded. The underlay: an
// animation::FrameUnderlay in the scene.
#include "cli/bag_camera_image.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "bag/bag_messages.h"
#include "bag/cdr_message.h"
#include "bag/cdr_reader.h"
#include "bag/topic_check.h"
#include "common/error.h"
#include "common/warnings.h"
#include "image/png_reader.h"

namespace urdfsnap::cli {
namespace {

// Numbers of a float64 array field.
std::vector<double> Numbers(const bag::MessageValue& array) {
  std::vector<double> numbers;
  for (const bag::MessageValue& item : array.items) numbers.push_back(item.number);
  return numbers;
}

}  // namespace

void BagCameraOptions::AddOptions(CLI::App& command, const std::string& moment) {
  command.add_option("--underlay-topic", underlay_topic,
                     "with a bag and a camera, draw the robot over this sensor_msgs/msg/Image or CompressedImage "
                     "topic's image at " + moment + " (the latest received whose stamp is not later), as "
                     "--underlay does with a file (default: none)");
  command.add_option("--camera-info-topic", camera_info_topic,
                     "with a bag, the camera's calibration is this sensor_msgs/msg/CameraInfo topic's latest "
                     "message at or before " + moment + ", instead of a --camera-info file (default: none)");
}

void BagCameraOptions::RequireBag(bool bag, const std::string& how) const {
  for (const auto& [topic, option] : {std::pair{&underlay_topic, "--underlay-topic"},
                                      std::pair{&camera_info_topic, "--camera-info-topic"}}) {
    if (!bag && !topic->empty()) throw Error(std::string(option) + ": a topic of a recording; " + how);
  }
}

camera::CameraInfo ReadBagCameraInfo(const std::string& path, const std::string& topic, std::int64_t time_ns) {
  const bag::TopicRequirement required{topic, {"sensor_msgs/CameraInfo"}, "--camera-info-topic",
                                       "sensor_msgs/msg/CameraInfo"};
  struct Kept {
    std::int64_t stamp_ns = 0;
    std::string where;
    std::vector<std::uint8_t> cdr;
  };
  std::optional<Kept> kept;
  std::shared_ptr<const bag::MessageSchema> schema;
  bool found = false;
  bag::ReadBagMessages(
      path,
      [&](const bag::BagTopic& t) {
        const bool match = bag::Matches(required, t, path);
        found = found || match;
        return match;
      },
      [&](const bag::BagMessage& message) {
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
  if (!found) throw Error(path + ": no topic '" + topic + "' (--camera-info-topic)");
  if (!kept) {
    throw Error(path + ": no message on '" + topic + "' at or before the moment drawn (stamp " +
                bag::TimeText(static_cast<std::uint64_t>(std::max<std::int64_t>(time_ns, 0))) +
                " s) (--camera-info-topic)");
  }
  bag::MessageValue m;
  try {
    m = bag::DecodeMessage(*schema, kept->cdr);
  } catch (const bag::CdrError& e) {
    throw Error(kept->where + ": not a sensor_msgs/CameraInfo in CDR: " + e.what());
  }
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
  camera::CheckCameraInfoMessage(info, kept->where);
  return info;
}

request::ResolvedRequest ResolveWithBagCamera(const request::RenderRequest& r, const BagCameraOptions& o,
                                              const std::string& bag, std::int64_t moment_ns, Warnings& warnings) {
  request::RequestFiles files = request::ReadRequestFiles(r, warnings);
  if (!o.camera_info_topic.empty()) {
    if (!r.camera_info.empty()) throw Error("--camera-info and --camera-info-topic: give one calibration");
    files.camera.info = ReadBagCameraInfo(bag, o.camera_info_topic, moment_ns);
    if (!r.size.empty()) {
      WarnIgnored(warnings, "--size " + r.size, "the size comes from the calibration (--camera-info-topic)");
    }
    // ReadRequestFiles reads an underlay only for a camera the options name
    if (!r.underlay.empty() && !files.camera.underlay) {
      files.camera.underlay = std::make_shared<const image::Image>(image::ReadPng(r.underlay));
    }
  }
  return request::ResolveRequest(r, files, request::CommandLineLabel);
}

void AddBagUnderlay(const BagCameraOptions& o, const request::RenderRequest& r, const std::string& bag,
                    double stamp_at_zero, BagScene& scene) {
  if (o.underlay_topic.empty()) return;
  if (!scene.robot.settings.camera) {
    throw Error("--underlay-topic needs a camera: --camera-info, --camera-frame or --camera-pose");
  }
  if (!r.underlay.empty()) throw Error("--underlay and --underlay-topic: give one camera image");
  scene.underlay.emplace(bag, o.underlay_topic, stamp_at_zero);
}

}  // namespace urdfsnap::cli
