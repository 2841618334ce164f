// Robot's lookups and the names of joint types.
#include "model/robot.h"

#include <algorithm>
#include <utility>

#include "model/forward_kinematics.h"

namespace urdfsnap::model {

namespace {

template <typename Element>
int IndexOfName(const std::vector<Element>& elements, std::string_view name) {
  const auto it = std::find_if(elements.begin(), elements.end(),
                               [&](const Element& e) { return e.name == name; });
  return it == elements.end() ? -1 : static_cast<int>(it - elements.begin());
}

}  // namespace

const char* JointTypeName(JointType type) {
  switch (type) {
    case JointType::kFixed: return "fixed";
    case JointType::kRevolute: return "revolute";
    case JointType::kContinuous: return "continuous";
    case JointType::kPrismatic: return "prismatic";
    case JointType::kFloating: return "floating";
    case JointType::kPlanar: return "planar";
  }
  return "unknown";
}

bool Joint::IsMovable() const {
  return type == JointType::kRevolute || type == JointType::kContinuous ||
         type == JointType::kPrismatic;
}

Robot::Robot(std::string name, std::string source, std::vector<Link> links,
             std::vector<Joint> joints)
    : name_(std::move(name)),
      source_(std::move(source)),
      links_(std::move(links)),
      joints_(std::move(joints)),
      kinematic_steps_(MakeKinematicSteps(links_, joints_)) {}

int Robot::FindLink(std::string_view name) const { return IndexOfName(links_, name); }

std::vector<std::string> Robot::LinkNames() const {
  std::vector<std::string> names;
  for (const Link& link : links_) names.push_back(link.name);
  return names;
}

std::vector<int> Robot::ParentLinks() const {
  std::vector<int> parents;
  for (const Link& link : links_) {
    parents.push_back(link.parent_joint >= 0 ? joints_[link.parent_joint].parent_link : -1);
  }
  return parents;
}

int Robot::FindJoint(std::string_view name) const { return IndexOfName(joints_, name); }

std::vector<std::string> Robot::MovableJointNames() const {
  std::vector<std::string> names;
  for (const Joint& joint : joints_) {
    if (joint.IsMovable() && joint.mimic_leader < 0) names.push_back(joint.name);
  }
  return names;
}

}  // namespace urdfsnap::model
