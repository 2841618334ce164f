// The frames RViz's TF display shows for a recording: the robot's links (posed by its joints, as
// robot_state_publisher would publish them) and every other frame the bag's /tf and /tf_static
// connect to them (odom, map, sensor frames not in the URDF), each with its TF parent, so that the
// display draws the axes, names and parent arrows of the whole tree, not only the robot's.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "model/robot.h"
#include "tf/tf_buffer.h"

namespace urdfsnap::motion {

class TfDisplayFrames {
 public:
  // The frames of `robot` and `buffer` (the bag's transforms, tf::ReadBagTransforms of `bag`).
  // A frame outside the robot is found through TF from the nearest link above it (a sensor frame
  // hung on a link that TF itself does not name), else from the first link TF names (odom and map
  // above the root); frames TF does not connect to the robot are left out, as RViz cannot place
  // them either. `stamp_at_zero`: the stamp (seconds since 1970) of trajectory time 0.
  TfDisplayFrames(const model::Robot& robot, std::shared_ptr<const tf::TfBuffer> buffer,
                  double stamp_at_zero, std::string bag);

  // Every frame's name: the robot's links in robot.links() order, then the others.
  const std::vector<std::string>& names() const { return names_; }
  // Per frame the index of its parent in names(), or -1: a link's parent link, or for a link
  // without one (the root) and the other frames, their TF parent when it is shown.
  const std::vector<int>& parents() const { return parents_; }

  // The pose of every frame in the scene's frame at trajectory time `t` (seconds), given the
  // links' poses there (X_SL, one per robot link, as scene::RobotScene::LinkPoses gives them).
  // Outside the recorded transforms the nearest one holds, with one warning.
  std::vector<Eigen::Isometry3d> Poses(const std::vector<Eigen::Isometry3d>& X_SL, double t,
                                       Warnings& warnings) const;

 private:
  std::shared_ptr<const tf::TfBuffer> buffer_;
  double stamp_at_zero_;
  std::string bag_;
  std::vector<int> anchors_;   // per frame after the links: the link it is looked up from
  std::size_t link_count_ = 0;
  std::vector<std::string> names_;
  std::vector<int> parents_;
};

}  // namespace urdfsnap::motion
