// ReadRobotDescription: ReadBagMessages on one topic, its size checked before it is decoded, the
// first message kept (the bag is read to its end: rosbag2 gives no way to stop a read early).
#include "bag/recorded_description.h"

#include <map>
#include <optional>

#include "bag/bag_messages.h"
#include "bag/cdr_message.h"
#include "bag/cdr_reader.h"
#include "common/error.h"
#include "common/file_reading.h"

namespace urdfsnap::bag {

std::string ReadRobotDescription(const std::string& path, const std::string& topic) {
  std::map<std::string, std::string> topics;  // every topic seen, with its type
  std::optional<std::string> description;
  const auto wanted = [&](const BagTopic& candidate) {
    topics.emplace(candidate.name, candidate.type);
    if (candidate.name != topic) return false;
    if (ShortTypeName(candidate.type) != "std_msgs/String" || candidate.encoding != "cdr") {
      throw Error(path + ": topic '" + topic + "' carries '" + candidate.type +
                  "' messages encoded as '" + candidate.encoding +
                  "'; a robot description is a std_msgs/msg/String in 'cdr' (ROS 2)");
    }
    return true;
  };
  ReadBagMessages(path, wanted, [&](const BagMessage& message) {
    if (description) return;
    const std::string where =
        DescribeMessage(message.file, topic, message.index, message.log_time);
    if (message.data.size() > kMaxTextFileBytes + 8) {  // the text, its length and the header
      throw Error(where + ": a robot description of " + std::to_string(message.data.size()) +
                  " bytes, more than urdfsnap's limit of " +
                  std::to_string(kMaxTextFileBytes >> 20) + " MiB for a model");
    }
    try {
      description = DecodeMessage(*message.topic.schema, message.data)["data"].text;
    } catch (const CdrError& e) {
      throw Error(where + ": not a std_msgs/msg/String in CDR: " + e.what());
    }
  });
  if (!description) {
    std::string list;
    for (const auto& [name, type] : topics) list += (list.empty() ? "" : ", ") + name + " (" + type + ")";
    throw Error(path + ": no robot description: no message on '" + topic + "'" +
                (topics.contains(topic) ? std::string() :
                 "; its topics are: " + (list.empty() ? std::string("none") : list)) +
                " (give the model as MODEL, or the topic with --description-topic)");
  }
  return *description;
}

}  // namespace urdfsnap::bag
