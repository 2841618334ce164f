// The JSON `urdfsnap info --json` prints about a robot: what `info` says in text, and the numbers
// a script wants besides (all limits, origins, masses, joint_state_publisher's defaults).
// Its format is documented by docs/info.schema.json.
#pragma once

#include <string>

#include "model/robot.h"

namespace urdfsnap::model {

// {"name", "source", "root", "links": [...], "joints": [...], "tree": [...]}:
// - links in tree order: {"name", "parent_joint" (null for the root), "child_joints", "visuals",
//   "collisions" (counts), "mass" (kg, null when the URDF gives none)};
// - joints in document order: {"name", "type", "parent", "child", "origin": {"xyz", "rpy"},
//   "axis" (unit vector, null for fixed and floating joints), "limits": {"lower", "upper" (null
//   for continuous joints), "velocity", "effort"} or null without a <limit>, "movable",
//   "default" (the value joint_state_publisher starts at, null for joints it does not move),
//   "mimic": {"joint", "multiplier", "offset"} or null};
// - tree: the links depth first, each {"link", "depth", "parent_link", "joint"} (null for the
//   root), a flat list so that a deep robot makes no deep JSON.
// Units are metres, radians, kilograms, seconds; invalid UTF-8 in names is replaced.
std::string DescribeRobotJson(const Robot& robot);

}  // namespace urdfsnap::model
