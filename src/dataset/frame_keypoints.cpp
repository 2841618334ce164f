// ProjectKeypoints: frames into the optical frame, through the camera model, checked against the
// depth and label images.
#include "dataset/frame_keypoints.h"

#include <cmath>
#include <initializer_list>

namespace urdfsnap::dataset {

namespace {

FrameKeypoint Project(const std::string& name, FrameKeypoint::Kind kind, const Eigen::Vector3d& p_C,
                      std::initializer_list<int> own_links, const camera::CameraModel& camera,
                      const image::DepthImage& depth, const image::LabelImage& labels) {
  FrameKeypoint k{name, kind, camera.Project(p_C), p_C.z(), false, false};
  if (!k.uv) return k;
  const double u = k.uv->x(), v = k.uv->y();
  // pixel (u, v) covers [u − 0.5, u + 0.5) x [v − 0.5, v + 0.5)
  k.in_image = u >= -0.5 && v >= -0.5 && u < camera.width() - 0.5 && v < camera.height() - 0.5;
  if (!k.in_image) return k;
  const size_t i = static_cast<size_t>(std::lround(v)) * camera.width() + static_cast<size_t>(std::lround(u));
  const int label = labels.labels[i];
  bool own = label == 0;
  for (int link : own_links) own = own || label == link + 1;
  k.visible = own || !(depth.metres[i] < p_C.z() - kOcclusionTolerance);
  return k;
}

}  // namespace

std::vector<FrameKeypoint> ProjectKeypoints(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_RL,
                                            const Eigen::Isometry3d& X_RC, const camera::CameraModel& camera,
                                            const image::DepthImage& depth, const image::LabelImage& labels) {
  const Eigen::Isometry3d X_CR = X_RC.inverse();
  std::vector<FrameKeypoint> keypoints;
  keypoints.reserve(robot.links().size() + robot.joints().size());
  for (size_t l = 0; l < robot.links().size(); ++l) {
    keypoints.push_back(Project(robot.links()[l].name, FrameKeypoint::Kind::kLink, X_CR * X_RL[l].translation(),
                                {static_cast<int>(l)}, camera, depth, labels));
  }
  for (const model::Joint& joint : robot.joints()) {
    // the joint frame is the child link's frame (URDF)
    keypoints.push_back(Project(joint.name, FrameKeypoint::Kind::kJoint, X_CR * X_RL[joint.child_link].translation(),
                                {joint.parent_link, joint.child_link}, camera, depth, labels));
  }
  return keypoints;
}

}  // namespace urdfsnap::dataset
