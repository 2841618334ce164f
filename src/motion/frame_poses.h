// The robot's joint positions in each frame of an animation: a trajectory's joints interpolated at
// the frame's time, every joint it does not name at the values the caller gives (-j, --joints) or
// urdfsnap's defaults, all resolved as `render` resolves one pose (model::ResolveJointPositions).
// Recorded and planned values are drawn as they are, as robot_state_publisher and RViz show them:
// a joint that leaves its limits gets one warning for the whole trajectory, and is clamped only
// when asked. Joints the robot lacks (a gripper's, a second robot's) are ignored with one warning.
#pragma once

#include <vector>

#include "common/warnings.h"
#include "model/joint_values.h"
#include "model/robot.h"
#include "motion/trajectory.h"

namespace urdfsnap::motion {

// How a trajectory's joints meet the robot's.
struct JointRules {
  // the defaults (-j, --joints) clamped to the limits as `render` clamps them (--no-clamp: false)
  bool clamp_defaults = true;
  // the trajectory's values clamped to the limits as joint_state_publisher's slider would
  // (--clamp); otherwise drawn as recorded
  bool clamp_trajectory = false;
  // a joint the robot does not have is an error rather than a warning (--strict-joints)
  bool strict_joints = false;
};

class FramePoses {
 public:
  // Checks `trajectory`'s joints against `robot`. Joints it does not have get one warning naming
  // them all ("joints.mcap: joints robot 'panda' does not have are ignored: 'finger1', ..."), or,
  // with rules.strict_joints, an Error located where the trajectory names the first ("plan.csv:1:
  // robot 'mrm' has no joint 'elbw'; its movable joints are: ..."), which is also the error when
  // none of the trajectory's joints is the robot's. Adds one warning for each joint
  // whose samples leave its limits: how far beyond, its furthest value and when it first left
  // (linear interpolation never goes beyond the samples). `defaults` are the values of the joints
  // the trajectory does not name; where both name a joint, the trajectory wins.
  FramePoses(const model::Robot& robot, const Trajectory& trajectory, model::NamedValues defaults,
             JointRules rules, Warnings& warnings);

  // One position per robot.joints() index (radians or metres) at trajectory time `t` (seconds, or
  // rows for a table without times; see FramePlan::TrajectoryTime). Warnings that
  // ResolveJointPositions gives for the pose (a fixed joint named, a mimic joint overridden) go to
  // `warnings`, which keeps each message once.
  std::vector<double> At(double t, Warnings& warnings) const;

 private:
  const model::Robot& robot_;
  const Trajectory& trajectory_;
  model::NamedValues values_;  // the defaults (clamped if asked), then one entry per used track
  std::size_t first_track_value_ = 0;
  std::vector<std::size_t> used_tracks_;  // the trajectory's tracks of joints the robot has
  std::vector<std::pair<double, double>> track_limits_;  // per used track; infinite unclamped
};

}  // namespace urdfsnap::motion
