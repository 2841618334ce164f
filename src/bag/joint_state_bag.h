// The JointState messages of one topic in a ROS 2 bag: an MCAP file, or a rosbag2 folder whose
// split files (NAME_0.mcap, NAME_1.mcap, ...) are read in order. Checks the topic's type and
// encoding, and turns every problem into one Error naming the file and, for a message, its number
// on the topic and its log time.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bag/joint_state_message.h"

namespace urdfsnap::bag {

// The topic robot_state_publisher listens to, and `ros2 bag record`'s usual JointState topic.
inline constexpr const char* kDefaultJointStateTopic = "/joint_states";

// One decoded message with where it came from.
struct BagJointState {
  const JointStateMessage& message;
  const std::string& file;  // the MCAP file it is in
  std::uint64_t index;      // 1 for the topic's first message (counted across split files)
  std::uint64_t log_time;   // nanoseconds, the bag's receive time
};

// "bag.mcap: message 12 on '/joint_states' (log time 1712345678.123456789 s)": where a message
// is, for errors about its content.
std::string DescribeMessage(const std::string& file, const std::string& topic, std::uint64_t index,
                            std::uint64_t log_time);

// The MCAP files of `path`: itself for a file; for a folder (what `ros2 bag record` makes) its
// .mcap files ordered by the number at the end of their names. Throws Error for a folder without
// .mcap files (naming .db3 files, if that is what it holds).
std::vector<std::string> BagFiles(const std::string& path);

// Calls `on_state` for every message on `topic`, in file order. Throws Error when the bag cannot be
// read, is truncated or corrupt, has no such topic (listing the topics it has, with their types),
// carries another type or encoding on it, has no message on it, or holds a message that does not
// decode. Exceptions from `on_state` pass through. Memory: one chunk of one file at a time.
void ReadJointStates(const std::string& path, const std::string& topic,
                     const std::function<void(const BagJointState&)>& on_state);

}  // namespace urdfsnap::bag
