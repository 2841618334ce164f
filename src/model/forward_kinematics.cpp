// Forward kinematics over the precomputed per-link steps: X_RC = X_RP * X_PC(q), parents first.
#include "model/forward_kinematics.h"

#include <cmath>
#include <string>

#include "common/error.h"

namespace urdfsnap::model {

namespace {

// [k]x, the matrix with [k]x v = k x v.
Eigen::Matrix3d CrossMatrix(const Eigen::Vector3d& k) {
  Eigen::Matrix3d K;
  K << 0, -k.z(), k.y(),
       k.z(), 0, -k.x(),
       -k.y(), k.x(), 0;
  return K;
}

}  // namespace

std::vector<KinematicStep> MakeKinematicSteps(const std::vector<Link>& links,
                                              const std::vector<Joint>& joints) {
  std::vector<KinematicStep> steps;
  steps.reserve(links.empty() ? 0 : links.size() - 1);
  for (size_t i = 1; i < links.size(); ++i) {
    const Joint& joint = joints[links[i].parent_joint];
    KinematicStep step;
    step.parent_link = joint.parent_link;
    step.joint = links[i].parent_joint;
    step.A = joint.X_PJ.linear();
    step.p = joint.X_PJ.translation();
    switch (joint.type) {
      case JointType::kRevolute:
      case JointType::kContinuous: {
        const Eigen::Matrix3d K = CrossMatrix(joint.axis);
        step.rotates = true;
        step.B = step.A * K;
        step.C = step.B * K;
        break;
      }
      case JointType::kPrismatic:
        step.d = step.A * joint.axis;
        break;
      case JointType::kFixed:
      case JointType::kFloating:  // drawn at their origin: see ResolveJointPositions
      case JointType::kPlanar:
        break;
    }
    steps.push_back(step);
  }
  return steps;
}

void ComputeLinkPoses(const Robot& robot, const std::vector<double>& positions,
                      std::vector<Eigen::Isometry3d>& X_RL) {
  if (positions.size() != robot.joints().size()) {
    throw Error("ComputeLinkPoses: robot '" + robot.name() + "' has " +
                std::to_string(robot.joints().size()) + " joints; " +
                std::to_string(positions.size()) + " positions given");
  }
  X_RL.resize(robot.links().size());
  if (X_RL.empty()) return;
  X_RL[0].setIdentity();
  const std::vector<KinematicStep>& steps = robot.kinematic_steps();
  for (size_t i = 0; i < steps.size(); ++i) {
    const KinematicStep& step = steps[i];
    const Eigen::Isometry3d& X_RP = X_RL[step.parent_link];
    Eigen::Isometry3d& X_RC = X_RL[i + 1];
    const double q = positions[step.joint];
    if (step.rotates) {
      const Eigen::Matrix3d R_PC = step.A + std::sin(q) * step.B + (1 - std::cos(q)) * step.C;
      X_RC.linear().noalias() = X_RP.linear() * R_PC;
      X_RC.translation().noalias() = X_RP.linear() * step.p;
    } else {
      X_RC.linear().noalias() = X_RP.linear() * step.A;
      X_RC.translation().noalias() = X_RP.linear() * (step.p + q * step.d);
    }
    X_RC.translation() += X_RP.translation();
    X_RC.makeAffine();
  }
}

std::vector<Eigen::Isometry3d> ComputeLinkPoses(const Robot& robot,
                                                const std::vector<double>& positions) {
  std::vector<Eigen::Isometry3d> X_RL;
  ComputeLinkPoses(robot, positions, X_RL);
  return X_RL;
}

}  // namespace urdfsnap::model
