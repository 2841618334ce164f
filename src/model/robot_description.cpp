// DescribeRobot: aligned plain-text tables of links and joints, and the link tree.
#include "model/robot_description.h"

#include <algorithm>

#include "common/number_text.h"

namespace urdfsnap::model {

namespace {

std::string Padded(const std::string& text, size_t width) {
  return text + std::string(width > text.size() ? width - text.size() : 0, ' ');
}

std::string Plural(size_t count, const char* noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

bool HasAxis(JointType type) {
  return type != JointType::kFixed && type != JointType::kFloating;
}

std::string JointDetails(const Robot& robot, const Joint& joint) {
  std::string text;
  if (HasAxis(joint.type)) {
    text += "  axis (" + FormatNumber(joint.axis.x()) + " " + FormatNumber(joint.axis.y()) + " " +
            FormatNumber(joint.axis.z()) + ")";
  }
  if (joint.has_limits) {
    text += "  limits [" + FormatNumber(joint.lower) + ", " + FormatNumber(joint.upper) + "] " +
            joint.Unit();
  }
  if (joint.mimic_leader >= 0) {
    text += "  mimic " + FormatNumber(joint.mimic_multiplier) + " * " +
            robot.joints()[joint.mimic_leader].name + " + " + FormatNumber(joint.mimic_offset);
  }
  return text;
}

}  // namespace

std::string DescribeRobot(const Robot& robot) {
  const std::vector<Link>& links = robot.links();
  const std::vector<Joint>& joints = robot.joints();
  size_t link_width = 0, joint_width = 0;
  for (const Link& link : links) link_width = std::max(link_width, link.name.size());
  for (const Joint& joint : joints) joint_width = std::max(joint_width, joint.name.size());

  std::string text = "robot '" + robot.name() + "' from " + robot.source() + ": " +
                     Plural(links.size(), "link") + ", " + Plural(joints.size(), "joint") + " (" +
                     std::to_string(robot.MovableJointNames().size()) + " movable)\n";

  text += "\nlinks:\n";
  for (const Link& link : links) {
    text += "  " + Padded(link.name, link_width) + "  " +
            Plural(link.visuals.size(), "visual") + ", " +
            Plural(link.collisions.size(), "collision") + "\n";
  }

  text += "\njoints:\n";
  for (const Joint& joint : joints) {
    text += "  " + Padded(joint.name, joint_width) + "  " + Padded(JointTypeName(joint.type), 10) +
            "  " + links[joint.parent_link].name + " -> " + links[joint.child_link].name +
            JointDetails(robot, joint) + "\n";
  }

  // links are in depth-first order, so each one's depth follows from its parent's; indentation
  // stops growing at kDeepest, deeper links say their depth (the output stays linear in size)
  constexpr int kDeepest = 32;
  text += "\ntree:\n";
  std::vector<int> depth(links.size(), 0);
  for (size_t i = 0; i < links.size(); ++i) {
    if (links[i].parent_joint >= 0) {
      const Joint& joint = joints[links[i].parent_joint];
      depth[i] = depth[joint.parent_link] + 1;
      text += "  " + std::string(2 * std::min(depth[i], kDeepest), ' ') +
              (depth[i] > kDeepest ? "(depth " + std::to_string(depth[i]) + ") " : "") +
              links[i].name + "  (" + joint.name + ", " + JointTypeName(joint.type) + ")\n";
    } else {
      text += "  " + links[i].name + "\n";
    }
  }
  return text;
}

}  // namespace urdfsnap::model
