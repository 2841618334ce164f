// The text `urdfsnap info` prints about a robot.
#pragma once

#include <string>

#include "model/robot.h"

namespace urdfsnap::model {

// Describes the robot in plain text: its name and source; its links with their number of visual
// and collision elements; its joints with type, parent and child, unit axis, limits (radians or
// metres) and mimic rule; and the tree of links, children indented under their parents.
std::string DescribeRobot(const Robot& robot);

}  // namespace urdfsnap::model
