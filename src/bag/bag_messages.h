// The messages of a ROS 2 bag whatever its storage (bag/rosbag2_folder.h): MCAP files, SQLite
// .db3 files, split and compressed as rosbag2 writes them, each topic with the definition its
// messages decode by: the bag's own (MCAP's ros2msg schemas), else the one urdfsnap ships.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "bag/message_schema.h"

namespace urdfsnap::bag {

struct BagTopic {
  std::string name;      // "/joint_states"
  std::string type;      // "sensor_msgs/msg/JointState"
  std::string encoding;  // "cdr" for ROS 2
  std::shared_ptr<const MessageSchema> schema;  // set for wanted topics
};

struct BagMessage {
  const BagTopic& topic;
  const std::string& file;   // the storage file it is in
  std::uint64_t index;       // 1 for the topic's first message (counted across split files)
  std::uint64_t log_time;    // nanoseconds, the bag's receive time
  std::span<const std::uint8_t> data;  // CDR, decompressed
};

// Reads every file of `path` in order. `wanted` sees each topic of each file once (without its
// schema) and says whether its messages are read; a wanted topic then gets its definition, and
// each of its messages goes to `on_message`, in the file's order. Throws urdfsnap::Error naming the
// file for an unreadable, corrupt or truncated file, and for a wanted topic whose definition
// cannot be read or is neither in the bag nor shipped. Exceptions from the callbacks pass through.
void ReadBagMessages(const std::string& path, const std::function<bool(const BagTopic&)>& wanted,
                     const std::function<void(const BagMessage&)>& on_message);

// "1712345678.123456789": a time in nanoseconds since 1970 as seconds, for messages.
std::string TimeText(std::uint64_t time_ns);

// "bag.mcap: message 12 on '/joint_states' (log time 1712345678.123456789 s)": where a message
// is, for errors about its content.
std::string DescribeMessage(const std::string& file, const std::string& topic, std::uint64_t index,
                            std::uint64_t log_time);

}  // namespace urdfsnap::bag
