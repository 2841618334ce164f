// Access to the ROS 2 message definitions of src/bag/msg/, compiled into the binary
// (cmake/EmbedFiles.cmake), for bags that store none.
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap::bag {

// The .msg text of src/bag/msg/<name> ("sensor_msgs.JointState.msg"); throws urdfsnap::Error for
// an unknown name.
std::string_view EmbeddedDefinition(std::string_view name);

}  // namespace urdfsnap::bag
