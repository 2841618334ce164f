// The robot description a ROS 2 bag recorded: the first std_msgs/msg/String on the topic
// robot_state_publisher publishes it on (/robot_description), as RViz's RobotModel display reads
// it with "Description Source: Topic".
#pragma once

#include <string>

namespace urdfsnap::bag {

inline constexpr const char* kDefaultDescriptionTopic = "/robot_description";

// The text of the first message on `topic` of the bag at `path` (any storage bag/bag_messages.h
// reads). Throws urdfsnap::Error naming the bag for a bag that cannot be read, no such topic
// (listing the topics it has), another type on it, no message on it, a message that does not
// decode, or a description longer than common/file_reading's limit for a text file (64 MiB).
std::string ReadRobotDescription(const std::string& path, const std::string& topic);

}  // namespace urdfsnap::bag
