// Joint motion for docs pages: mimic followers, moving subtrees, stills and sweeps.
#include "docs/joint_sweeps.h"

#include <numbers>

namespace urdfsnap::docs {

namespace {

// The joint at the top of `joint`'s mimic chain (itself when it is not a mimic). Chains end:
// the loader refuses mimic cycles.
int MimicRoot(const model::Robot& robot, int joint) {
  while (robot.joints()[joint].mimic_leader >= 0) joint = robot.joints()[joint].mimic_leader;
  return joint;
}

}  // namespace

std::vector<int> MimicFollowers(const model::Robot& robot, int joint) {
  std::vector<int> followers;
  for (int j = 0; j < static_cast<int>(robot.joints().size()); ++j) {
    if (j != joint && robot.joints()[j].mimic_leader >= 0 && MimicRoot(robot, j) == joint) followers.push_back(j);
  }
  return followers;
}

std::vector<int> MovingLinks(const model::Robot& robot, int joint) {
  const auto& links = robot.links();
  const auto& joints = robot.joints();
  std::vector<bool> moving(links.size(), false);
  moving[joints[joint].child_link] = true;
  for (int follower : MimicFollowers(robot, joint)) moving[joints[follower].child_link] = true;
  // parents come before their children, so one pass carries motion down the tree
  std::vector<int> result;
  for (size_t i = 0; i < links.size(); ++i) {
    const int parent_joint = links[i].parent_joint;
    if (parent_joint >= 0 && moving[joints[parent_joint].parent_link]) moving[i] = true;
    if (moving[i]) result.push_back(static_cast<int>(i));
  }
  return result;
}

std::vector<StillPose> StillPoses(const model::Joint& joint, double default_position) {
  if (joint.type == model::JointType::kContinuous) {
    constexpr double kQuarter = std::numbers::pi / 2;
    return {{"quarter turn back", "quarter-back", default_position - kQuarter},
            {"default", "default", default_position},
            {"quarter turn forward", "quarter-forward", default_position + kQuarter},
            {"half turn (either way)", "half-turn", default_position + 2 * kQuarter}};
  }
  return {{"lower limit", "lower", joint.lower},
          {"default", "default", default_position},
          {"upper limit", "upper", joint.upper}};
}

std::vector<double> SweepPositions(const model::Joint& joint, double default_position, int frames) {
  std::vector<double> positions(frames);
  if (joint.type == model::JointType::kContinuous) {
    for (int k = 0; k < frames; ++k) positions[k] = default_position + 2 * std::numbers::pi * k / frames;
    return positions;
  }
  // the path default → upper → lower → default, walked at an even speed
  const double up = joint.upper - default_position;
  const double across = joint.upper - joint.lower;
  const double length = 2 * across;
  for (int k = 0; k < frames; ++k) {
    const double s = length * k / frames;
    if (s <= up) {
      positions[k] = default_position + s;
    } else if (s <= up + across) {
      positions[k] = joint.upper - (s - up);
    } else {
      positions[k] = joint.lower + (s - up - across);
    }
  }
  return positions;
}

}  // namespace urdfsnap::docs
