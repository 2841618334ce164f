// ReadJointStates: ReadBagMessages on one topic, type checks, decoding with located errors.
#include "bag/joint_state_bag.h"

#include <map>

#include "bag/cdr_reader.h"
#include "common/error.h"

namespace urdfsnap::bag {
namespace {

std::string TopicList(const std::map<std::string, std::string>& topics) {
  std::string list;
  for (const auto& [topic, type] : topics) {
    list += (list.empty() ? "" : ", ") + topic + " (" + (type.empty() ? "no schema" : type) + ")";
  }
  return list;
}

}  // namespace

void ReadJointStates(const std::string& path, const std::string& topic,
                     const std::function<void(const BagJointState&)>& on_state) {
  std::map<std::string, std::string> topics;  // every topic seen, with its type
  bool has_topic = false;
  std::uint64_t count = 0;
  JointStateMessage decoded;
  const auto wanted = [&](const BagTopic& candidate) {
    topics.emplace(candidate.name, candidate.type);
    if (candidate.name != topic) return false;
    if (ShortTypeName(candidate.type) != ShortTypeName(kJointStateType) ||
        candidate.encoding != "cdr") {
      throw Error(path + ": topic '" + topic + "' carries '" + candidate.type +
                  "' messages encoded as '" + candidate.encoding + "'; urdfsnap reads " +
                  kJointStateType + " in 'cdr' (ROS 2)");
    }
    has_topic = true;
    return true;
  };
  ReadBagMessages(path, wanted, [&](const BagMessage& message) {
    ++count;
    try {
      DecodeJointState(*message.topic.schema, message.data, decoded);
    } catch (const CdrError& e) {
      throw Error(DescribeMessage(message.file, topic, message.index, message.log_time) +
                  ": not a JointState in CDR: " + e.what());
    }
    on_state(BagJointState{decoded, message.file, message.index, message.log_time});
  });
  if (!has_topic) {
    throw Error(path + ": no topic '" + topic + "' in the bag; " +
                (topics.empty() ? std::string("it has no topics")
                                : "its topics are: " + TopicList(topics)));
  }
  if (count == 0) throw Error(path + ": no messages on '" + topic + "'");
}

}  // namespace urdfsnap::bag
