// SampleJointPositions and SampleCameraPose.
#include "dataset/sampling.h"

#include <cmath>
#include <numbers>

#include "model/joint_values.h"

namespace urdfsnap::dataset {

std::vector<double> SampleJointPositions(const model::Robot& robot, SampleRandom& random, Warnings& warnings) {
  model::NamedValues given;
  for (const model::Joint& joint : robot.joints()) {
    if (!joint.IsMovable() || joint.mimic_leader >= 0) continue;
    // every joint draws one number, so adding a limit to one joint does not move the others'
    const double fraction = random.Uniform(0, 1);
    if (joint.type == model::JointType::kContinuous) {
      given.push_back({joint.name, -std::numbers::pi + 2 * std::numbers::pi * fraction});
    } else if (joint.has_limits) {
      given.push_back({joint.name, joint.lower + (joint.upper - joint.lower) * fraction});
    }
  }
  return model::ResolveJointPositions(robot, given, true, warnings);
}

Eigen::Isometry3d SampleCameraPose(const Eigen::Vector3d& centre, Interval distance, Interval elevation_deg,
                                   SampleRandom& random) {
  const double d = random.Uniform(distance.low, distance.high);
  const double elevation = random.Uniform(elevation_deg.low, elevation_deg.high) * std::numbers::pi / 180;
  const double azimuth = random.Uniform(0, 2 * std::numbers::pi);
  const Eigen::Vector3d towards_eye(std::cos(azimuth) * std::cos(elevation), std::sin(azimuth) * std::cos(elevation),
                                    std::sin(elevation));
  const Eigen::Vector3d z = -towards_eye;
  // x horizontal and to the right of the view; straight above or below, the azimuth decides it
  Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ());
  if (x.norm() < 1e-9) x = Eigen::Vector3d(-std::sin(azimuth), std::cos(azimuth), 0);
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
  X_WC.linear() << x, y, z;
  X_WC.translation() = centre + d * towards_eye;
  return X_WC;
}

}  // namespace urdfsnap::dataset
