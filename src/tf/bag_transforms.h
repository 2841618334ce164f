// The transforms a ROS 2 bag recorded on /tf and /tf_static (tf2_msgs/msg/TFMessage) in a
// TfBuffer: static ones collected across every split file, dynamic ones by their header stamps.
#pragma once

#include <string>

#include "tf/tf_buffer.h"

namespace urdfsnap::tf {

inline constexpr const char* kTfTopic = "/tf";
inline constexpr const char* kTfStaticTopic = "/tf_static";

// Reads every TFMessage on /tf and /tf_static of the bag at `path` (any storage bag/bag_messages.h
// reads); a bag without them gives an empty buffer. Frame names lose a leading '/', as tf2 strips
// it. Throws urdfsnap::Error naming the file and message for a bag that cannot be read, another
// type on those topics, a message that does not decode, or a transform TfBuffer::Add refuses.
TfBuffer ReadBagTransforms(const std::string& path);

}  // namespace urdfsnap::tf
