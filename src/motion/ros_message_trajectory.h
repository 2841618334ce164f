// Trajectories as ROS messages in YAML or JSON, the way MoveIt plans them and `ros2 topic echo`
// prints them: a trajectory_msgs/JointTrajectory (joint_names, points with positions and
// time_from_start), the same inside a moveit_msgs RobotTrajectory (joint_trajectory:) or
// DisplayTrajectory (trajectory: [...], played one after the other as RViz does), or a stream of
// sensor_msgs/JointState messages (YAML documents separated by `---`, times from header.stamp).
#pragma once

#include <string>
#include <string_view>

#include "motion/trajectory.h"

namespace urdfsnap::motion {

// Parses YAML (JSON is read as the YAML it is) holding one trajectory or any number of JointState
// messages; a top-level list is read as a list of messages. time_from_start and header.stamp are
// {sec, nanosec} (ROS 1's {secs, nsecs} too) or seconds. JointTrajectory times count from 0,
// JointState times from the first message. Throws Error "PATH:LINE: ..." for bad YAML, a document
// of another kind, a missing field, a value that is not a finite number, lists of different
// lengths, times that do not increase, several trajectories, or nothing to animate.
Trajectory ParseRosMessageTrajectory(std::string_view text, const std::string& path);

}  // namespace urdfsnap::motion
