// The JointState messages of one topic in a ROS 2 bag (any storage bag/bag_messages.h reads: an
// MCAP file, a .db3 file, a rosbag2 folder of split, compressed files). Checks the topic's type
// and encoding, and turns every problem into one Error naming the file and, for a message, its
// number on the topic and its log time.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "bag/bag_messages.h"
#include "bag/joint_state_message.h"

namespace urdfsnap::bag {

// The topic robot_state_publisher listens to, and `ros2 bag record`'s usual JointState topic.
inline constexpr const char* kDefaultJointStateTopic = "/joint_states";

// One decoded message with where it came from.
struct BagJointState {
  const JointStateMessage& message;
  const std::string& file;  // the storage file it is in
  std::uint64_t index;      // 1 for the topic's first message (counted across split files)
  std::uint64_t log_time;   // nanoseconds, the bag's receive time
};

// Calls `on_state` for every message on `topic`, in file order. Throws Error when the bag cannot be
// read, is truncated or corrupt, has no such topic (listing the topics it has, with their types),
// carries another type or encoding on it, has no message on it, or holds a message that does not
// decode. Exceptions from `on_state` pass through. Memory: one chunk of one file at a time.
void ReadJointStates(const std::string& path, const std::string& topic,
                     const std::function<void(const BagJointState&)>& on_state);

}  // namespace urdfsnap::bag
