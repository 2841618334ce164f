// Forward kinematics: the pose of every link in the root link's frame for one joint vector.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "model/kinematic_step.h"
#include "model/robot.h"

namespace urdfsnap::model {

// Computes X_RL, the pose of every link L in the root link frame R (metres), indexed as
// robot.links(); X_RL[0] is the identity. `positions` holds one value per robot.joints() index
// (radians or metres), mimic joints already resolved, as ResolveJointPositions returns them.
// Floating and planar joints stay at their origin. Resizes X_RL only when its size differs, so a
// caller that keeps the vector between frames does not allocate. Throws Error when `positions`
// has the wrong size.
void ComputeLinkPoses(const Robot& robot, const std::vector<double>& positions,
                      std::vector<Eigen::Isometry3d>& X_RL);

// As above, returning a new vector.
std::vector<Eigen::Isometry3d> ComputeLinkPoses(const Robot& robot,
                                                const std::vector<double>& positions);

// Folds each non-root link's joint origin, axis and type into a KinematicStep (links in tree
// order, joints indexed by them). Robot's constructor calls this once.
std::vector<KinematicStep> MakeKinematicSteps(const std::vector<Link>& links,
                                              const std::vector<Joint>& joints);

}  // namespace urdfsnap::model
