// Assignments from the command line and the resolution of a full joint vector the way
// joint_state_publisher (ROS) fills in, clamps and mimics joint values.
#include "model/joint_values.h"

#include <algorithm>
#include <functional>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap::model {

namespace {

std::string Quoted(const std::string& text) { return "'" + text + "'"; }

// joint_state_publisher's start value: 0, unless 0 is outside the limits (its "zero" rule).
double DefaultPosition(const Joint& joint) {
  if (joint.has_limits && (joint.lower > 0 || joint.upper < 0)) {
    return (joint.lower + joint.upper) / 2;
  }
  return 0;
}

[[noreturn]] void ThrowUnknownJoint(const Robot& robot, const std::string& name) {
  std::string movable;
  for (const std::string& joint : robot.MovableJointNames()) {
    movable += (movable.empty() ? "" : ", ") + joint;
  }
  std::string message = "robot " + Quoted(robot.name()) + " has no joint " + Quoted(name);
  if (robot.FindLink(name) >= 0) message += " (" + Quoted(name) + " is a link)";
  message += movable.empty() ? "; it has no movable joints"
                             : "; its movable joints are: " + movable;
  throw Error(message);
}

}  // namespace

void ParseJointAssignment(const std::string& text, NamedValues& out) {
  const size_t equals = text.find('=');
  double value = 0;
  if (equals == std::string::npos || equals == 0 ||
      !ParseNumber(std::string_view(text).substr(equals + 1), value)) {
    throw Error("--joint " + Quoted(text) +
                ": expected NAME=VALUE with VALUE a number in radians or metres");
  }
  out.emplace_back(text.substr(0, equals), value);
}

std::vector<double> ResolveJointPositions(const Robot& robot, const NamedValues& given, bool clamp,
                                          Warnings& warnings) {
  const std::vector<Joint>& joints = robot.joints();
  std::vector<double> positions(joints.size());
  std::vector<bool> is_given(joints.size(), false);
  for (size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].IsMovable()) positions[j] = DefaultPosition(joints[j]);
  }

  for (const auto& [name, value] : given) {
    const int j = robot.FindJoint(name);
    if (j < 0) ThrowUnknownJoint(robot, name);
    const Joint& joint = joints[j];
    if (!joint.IsMovable()) {
      warnings.Add("joint " + Quoted(name) + " is " + JointTypeName(joint.type) +
                   "; the value given for it is ignored");
      continue;
    }
    if (joint.mimic_leader >= 0) {
      warnings.Add("joint " + Quoted(name) + " mimics joint " +
                   Quoted(joints[joint.mimic_leader].name) +
                   "; the value given for it overrides the mimic rule");
    }
    double position = value;
    if (clamp && joint.has_limits && (value < joint.lower || value > joint.upper)) {
      position = std::clamp(value, joint.lower, joint.upper);
      warnings.Add("joint " + Quoted(name) + ": " + FormatForPeople(value, joint.Unit()) +
                   " is outside its limits, " + FormatRangeForPeople(joint.lower, joint.upper, joint.Unit()) +
                   "; clamped to " + FormatForPeople(position, joint.Unit()) +
                   " as joint_state_publisher's slider would (--no-clamp keeps it)");
    }
    positions[j] = position;
    is_given[j] = true;
  }

  // mimic joints follow their leaders, which may be mimic joints themselves (the loader has
  // ruled out circles)
  std::vector<bool> resolved = is_given;
  const std::function<double(int)> resolve = [&](int j) {
    const Joint& joint = joints[j];
    if (!resolved[j] && joint.mimic_leader >= 0) {
      positions[j] = joint.mimic_multiplier * resolve(joint.mimic_leader) + joint.mimic_offset;
    }
    resolved[j] = true;
    return positions[j];
  };
  for (size_t j = 0; j < joints.size(); ++j) resolve(static_cast<int>(j));

  for (const Joint& joint : joints) {
    if (joint.type == JointType::kFloating || joint.type == JointType::kPlanar) {
      warnings.Add("joint " + Quoted(joint.name) + " is " + JointTypeName(joint.type) +
                   "; urdfsnap draws it at its origin");
    }
  }
  return positions;
}

}  // namespace urdfsnap::model
