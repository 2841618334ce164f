// The topic a command option names in a bag (--underlay-topic, --camera-info-topic), checked to
// carry a type the option reads in CDR (ROS 2): inside a ReadBagMessages pass (Matches), or on its
// own when nothing arrived on it and the reason is wanted for the error (RequireTopic).
#pragma once

#include <string>
#include <vector>

#include "bag/bag_messages.h"

namespace urdfsnap::bag {

struct TopicRequirement {
  std::string topic;               // "/camera/image_raw"
  std::vector<std::string> types;  // short names: "sensor_msgs/Image"
  std::string option;              // "--underlay-topic"
  std::string what;                // what the option reads: "sensor_msgs/msg/Image and CompressedImage"
};

// For ReadBagMessages' `wanted`: whether `topic` (of the bag at `path`) is the one required. Throws
// urdfsnap::Error "PATH: OPTION 'TOPIC' carries 'TYPE' messages encoded as 'ENC'; ..." when it is
// but carries another type or encoding.
bool Matches(const TopicRequirement& required, const BagTopic& topic, const std::string& path);

// Reads the bag's topics (no messages) and throws urdfsnap::Error as Matches does, or "PATH: no
// topic 'TOPIC' (OPTION)" when the bag has no such topic.
void RequireTopic(const TopicRequirement& required, const std::string& path);

}  // namespace urdfsnap::bag
