// `GET /api/robot`: the robot's movable joints as joint_state_publisher_gui shows them, as JSON.
#pragma once

#include <string>
#include <vector>

#include "model/robot.h"

namespace urdfsnap::serve {

// {"name": ROBOT, "joints": [{"name", "type", "lower", "upper", "default", "mimic"}, ...],
//  "links": [NAME, ...] (tree order: what the page's focus list offers), "warnings": [...]} with joint_state_publisher_gui's rules (joint_state_publisher.py): only
// revolute, continuous and prismatic joints; the range is the URDF limits, ±π for continuous
// joints; the default is the value it starts at (0, or the middle of the limits when 0 is
// outside them); a mimic joint has "mimic": {"joint", "multiplier", "offset"} and gets no slider
// (it follows its leader), the others "mimic": null. Joints in document order.
std::string PageRobotJson(const model::Robot& robot, const std::vector<std::string>& warnings);

}  // namespace urdfsnap::serve
