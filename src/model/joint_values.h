// Joint values: NAME=VALUE assignments from the command line, joint files, and the full joint
// vector with joint_state_publisher's defaults, slider clamping and mimic rules applied.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "common/warnings.h"
#include "model/robot.h"

namespace urdfsnap::model {

// Joint names with values (radians or metres), in the order given; a later entry for the same
// name wins.
using NamedValues = std::vector<std::pair<std::string, double>>;

// Appends the assignment "NAME=VALUE" (VALUE a finite number in radians or metres) to `out`.
// Throws Error naming the option the text comes from ("--joint 'elbow=bent': ...") when there
// is no '=', no name or no number after it.
void ParseJointAssignment(const std::string& text, NamedValues& out);

// Reads a joint file: YAML, or JSON when the name ends in ".json". Either a map {name: value} or
// ROS JointState-style {name: [...], position: [...]} (other keys such as velocity are ignored).
// Throws Error "path:line: ..." when the file cannot be read or parsed or has the wrong shape.
NamedValues ReadJointFile(const std::string& path);

// ReadJointFile for the text of a file already read; `path` picks the format and names the file.
NamedValues ParseJointFile(const std::string& text, const std::string& path);

// One position per robot.joints() index (radians or metres), as joint_state_publisher would
// publish them:
// - a joint not in `given` takes 0, or the middle of its limits when 0 is outside them;
// - a value outside a joint's limits is clamped with one warning each, unless clamp is false;
// - a mimic joint follows multiplier * leader + offset; a value given for it overrides the rule
//   (as a published joint state does in RViz), with a warning;
// - a value for a fixed joint is ignored with a warning; floating and planar joints stay at their
//   origin with a warning.
// Throws Error for a name that is not a joint of the robot, listing its movable joints.
std::vector<double> ResolveJointPositions(const Robot& robot, const NamedValues& given, bool clamp,
                                          Warnings& warnings);

}  // namespace urdfsnap::model
