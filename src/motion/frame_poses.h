// The robot's joint positions in each frame of an animation: a trajectory's joints interpolated at
// the frame's time, every joint it does not name at the values the caller gives (-j, --joints) or
// urdfsnap's defaults, all resolved as `render` resolves one pose (model::ResolveJointPositions).
// Limits are clamped in every frame, with one warning per joint for the whole trajectory rather
// than one per frame.
#pragma once

#include <vector>

#include "common/warnings.h"
#include "model/joint_values.h"
#include "model/robot.h"
#include "motion/trajectory.h"

namespace urdfsnap::motion {

class FramePoses {
 public:
  // Checks `trajectory`'s joints against `robot`: a joint it does not have is an Error located
  // where the trajectory names it ("plan.csv:1: robot 'mrm' has no joint 'elbw'; its movable
  // joints are: ..."). With `clamp`, adds to `warnings` one warning for each joint whose samples
  // leave its limits (the furthest value and when), since linear interpolation never goes beyond
  // the samples; frames are then clamped without further warnings. `defaults` are the values of
  // the joints the trajectory does not name; where both name a joint, the trajectory wins.
  FramePoses(const model::Robot& robot, const Trajectory& trajectory, model::NamedValues defaults,
             bool clamp, Warnings& warnings);

  // One position per robot.joints() index (radians or metres) at trajectory time `t` (seconds, or
  // rows for a table without times; see FramePlan::TrajectoryTime). Warnings that
  // ResolveJointPositions gives for the pose (a fixed joint named, a mimic joint overridden) go to
  // `warnings`, which keeps each message once.
  std::vector<double> At(double t, Warnings& warnings) const;

 private:
  const model::Robot& robot_;
  const Trajectory& trajectory_;
  model::NamedValues values_;  // the defaults, then one entry per trajectory track
  std::size_t first_track_value_ = 0;
  std::vector<std::pair<double, double>> track_limits_;  // per track; infinite when unclamped
  bool clamp_;
};

}  // namespace urdfsnap::motion
