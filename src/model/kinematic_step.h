// One link's forward kinematics with everything that does not depend on the joint value folded
// in at load time, so the per-frame pass is a handful of multiply-adds and one sin/cos per joint.
#pragma once

#include <Eigen/Core>

namespace urdfsnap::model {

// The pose of a child link C in its parent P as a function of its joint's value q:
//   R_PC(q) = A + sin(q) B + (1 - cos(q)) C     (rotation; A alone when the joint does not rotate)
//   p_PC(q) = p + q d                            (d = 0 unless the joint slides)
// For a revolute joint with unit axis k in the joint frame, A = R_PJ, B = R_PJ [k]x and
// C = R_PJ [k]x^2 (Rodrigues' formula); for a prismatic one d = R_PJ k.
struct KinematicStep {
  bool rotates = false;
  int parent_link = -1;  // index into Robot::links(); always before this step's link
  int joint = -1;        // index into Robot::joints() and into the joint positions
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
};

}  // namespace urdfsnap::model
