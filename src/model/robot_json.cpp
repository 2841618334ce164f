// DescribeRobotJson: the robot's records as nlohmann::json, rounded where they were computed.
#include "model/robot_json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "model/joint_values.h"

namespace urdfsnap::model {

namespace {

using json = nlohmann::ordered_json;   // keys in the order written here, the documented one

// A number computed from a rotation matrix, to 12 significant digits: 1.57079632679 rather than
// 1.5707963267948963, 0 rather than 2.2e-16. Values read from the file are printed as they are.
double Rounded(double value) {
  if (std::abs(value) < 1e-12) return 0;
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", value);
  return std::strtod(text, nullptr);
}

json Vector(const Eigen::Vector3d& v) { return json::array({Rounded(v.x()), Rounded(v.y()), Rounded(v.z())}); }

// URDF's rpy: fixed-axis roll about x, then pitch about y, then yaw about z (R = Rz Ry Rx).
Eigen::Vector3d RollPitchYaw(const Eigen::Matrix3d& r) {
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  if (std::abs(r(2, 0)) > 1 - 1e-12) {
    // gimbal lock: only roll - yaw (pitch +90°) or roll + yaw (-90°) is defined; yaw takes 0
    return {std::atan2(-r(1, 2), r(1, 1)), pitch, 0};
  }
  return {std::atan2(r(2, 1), r(2, 2)), pitch, std::atan2(r(1, 0), r(0, 0))};
}

json Limits(const Joint& joint) {
  if (!joint.has_limits && !joint.velocity) return nullptr;
  const auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  return {{"lower", joint.has_limits ? json(joint.lower) : json(nullptr)},
          {"upper", joint.has_limits ? json(joint.upper) : json(nullptr)},
          {"velocity", optional(joint.velocity)},
          {"effort", optional(joint.effort)}};
}

json Joints(const Robot& robot) {
  Warnings ignored;
  const std::vector<double> defaults = ResolveJointPositions(robot, {}, true, ignored);
  const std::vector<Joint>& joints = robot.joints();
  json out = json::array();
  for (size_t j = 0; j < joints.size(); ++j) {
    const Joint& joint = joints[j];
    const bool has_axis = joint.type != JointType::kFixed && joint.type != JointType::kFloating;
    json mimic = nullptr;
    if (joint.mimic_leader >= 0) {
      mimic = {{"joint", joints[joint.mimic_leader].name},
               {"multiplier", joint.mimic_multiplier},
               {"offset", joint.mimic_offset}};
    }
    out.push_back({{"name", joint.name},
                   {"type", JointTypeName(joint.type)},
                   {"parent", robot.links()[joint.parent_link].name},
                   {"child", robot.links()[joint.child_link].name},
                   {"origin", {{"xyz", Vector(joint.X_PJ.translation())},
                               {"rpy", Vector(RollPitchYaw(joint.X_PJ.linear()))}}},
                   {"axis", has_axis ? Vector(joint.axis) : json(nullptr)},
                   {"limits", Limits(joint)},
                   {"movable", joint.IsMovable()},
                   {"default", joint.IsMovable() ? json(defaults[j]) : json(nullptr)},
                   {"mimic", mimic}});
  }
  return out;
}

json Links(const Robot& robot) {
  const std::vector<Link>& links = robot.links();
  std::vector<json> children(links.size(), json::array());
  for (const Joint& joint : robot.joints()) children[joint.parent_link].push_back(joint.name);
  json out = json::array();
  for (size_t i = 0; i < links.size(); ++i) {
    const Link& link = links[i];
    out.push_back({{"name", link.name},
                   {"parent_joint", link.parent_joint >= 0 ? json(robot.joints()[link.parent_joint].name)
                                                           : json(nullptr)},
                   {"child_joints", children[i]},
                   {"visuals", link.visuals.size()},
                   {"collisions", link.collisions.size()},
                   {"mass", link.mass ? json(*link.mass) : json(nullptr)}});
  }
  return out;
}

// Links are in depth-first order already (Robot's invariant); each one's depth is its parent's + 1.
json Tree(const Robot& robot) {
  const std::vector<Link>& links = robot.links();
  std::vector<int> depth(links.size(), 0);
  json out = json::array();
  for (size_t i = 0; i < links.size(); ++i) {
    json parent = nullptr, joint_name = nullptr;
    if (links[i].parent_joint >= 0) {
      const Joint& joint = robot.joints()[links[i].parent_joint];
      depth[i] = depth[joint.parent_link] + 1;
      parent = links[joint.parent_link].name;
      joint_name = joint.name;
    }
    out.push_back({{"link", links[i].name}, {"depth", depth[i]}, {"parent_link", parent}, {"joint", joint_name}});
  }
  return out;
}

}  // namespace

std::string DescribeRobotJson(const Robot& robot) {
  const json description = {{"name", robot.name()},
                            {"source", robot.source()},
                            {"root", robot.links().front().name},
                            {"links", Links(robot)},
                            {"joints", Joints(robot)},
                            {"tree", Tree(robot)}};
  // names come from the URDF: replace invalid UTF-8 rather than throw
  return description.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace urdfsnap::model
