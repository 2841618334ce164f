// ReadBagTransforms: ReadBagMessages on the two TF topics, each TFMessage decoded by its
// definition (the bag's or the shipped tf2_msgs/TFMessage) and its transforms added in order.
#include "tf/bag_transforms.h"

#include "bag/bag_messages.h"
#include "bag/cdr_message.h"
#include "bag/cdr_reader.h"
#include "common/error.h"

namespace urdfsnap::tf {
namespace {

constexpr const char* kTfMessageType = "tf2_msgs/TFMessage";

std::string WithoutSlash(const std::string& frame) {
  return !frame.empty() && frame.front() == '/' ? frame.substr(1) : frame;
}

// The TransformStamped `value` of a decoded TFMessage.
StampedTransform Stamped(const bag::MessageValue& value) {
  StampedTransform t;
  const bag::MessageValue& stamp = value["header"]["stamp"];
  t.stamp_ns = static_cast<std::int64_t>(stamp["sec"].number) * 1'000'000'000 +
               static_cast<std::int64_t>(stamp["nanosec"].number);
  t.parent = WithoutSlash(value["header"]["frame_id"].text);
  t.child = WithoutSlash(value["child_frame_id"].text);
  const bag::MessageValue& translation = value["transform"]["translation"];
  const bag::MessageValue& rotation = value["transform"]["rotation"];
  t.translation = {translation["x"].number, translation["y"].number, translation["z"].number};
  t.rotation = Eigen::Quaterniond(rotation["w"].number, rotation["x"].number,
                                  rotation["y"].number, rotation["z"].number);
  return t;
}

}  // namespace

TfBuffer ReadBagTransforms(const std::string& path) {
  TfBuffer buffer;
  const auto wanted = [&](const bag::BagTopic& topic) {
    if (topic.name != kTfTopic && topic.name != kTfStaticTopic) return false;
    if (bag::ShortTypeName(topic.type) != kTfMessageType || topic.encoding != "cdr") {
      throw Error(path + ": topic '" + topic.name + "' carries '" + topic.type +
                  "' messages encoded as '" + topic.encoding +
                  "'; urdfsnap reads tf2_msgs/msg/TFMessage in 'cdr' (ROS 2)");
    }
    return true;
  };
  bag::ReadBagMessages(path, wanted, [&](const bag::BagMessage& message) {
    const std::string where =
        bag::DescribeMessage(message.file, message.topic.name, message.index, message.log_time);
    std::vector<StampedTransform> transforms;
    try {
      const bag::MessageValue decoded = bag::DecodeMessage(*message.topic.schema, message.data);
      for (const bag::MessageValue& item : decoded["transforms"].items) {
        transforms.push_back(Stamped(item));
      }
    } catch (const bag::CdrError& e) {
      throw Error(where + ": not a TFMessage in CDR: " + e.what());
    }
    for (const StampedTransform& t : transforms) {
      buffer.Add(t, message.topic.name == kTfStaticTopic, where);
    }
  });
  return buffer;
}

}  // namespace urdfsnap::tf
