// Trajectories from ROS 2 bags: the sensor_msgs/msg/JointState messages of one topic of an MCAP
// file or rosbag2 folder, timed by their header stamps.
#pragma once

#include <string>

#include "common/warnings.h"
#include "motion/trajectory.h"

namespace urdfsnap::motion {

// Reads the JointStates on `topic` (see bag::ReadJointStates) into a trajectory whose times count
// from the first message's header.stamp, each position holding until the joint's next message
// (Between::kHold). When that stamp is zero (a publisher that does not stamp
// its messages) every message is timed by its log time instead, with a warning. Throws Error for
// every problem of the bag and for messages JointStateTracks refuses, naming the message's number
// on the topic and its log time.
Trajectory ReadBagTrajectory(const std::string& path, const std::string& topic, Warnings& warnings);

}  // namespace urdfsnap::motion
