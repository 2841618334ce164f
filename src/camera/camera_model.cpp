// CameraModel: calibration to the image's intrinsics, pose offset, projection and remap.
#include "camera/camera_model.h"

#include "common/error.h"

namespace urdfsnap::camera {

CameraModel::CameraModel(const CameraInfo& info, bool distort, Clipping clipping) : clipping_(clipping) {
  image_.width = info.width;
  image_.height = info.height;
  if (distort) {
    image_.k = info.RawIntrinsics();
    distortion_ = info.distortion;
    if (distortion_.Any()) {
      distortion_model_ = info.distortion_model;
      remap_ = std::make_shared<const DistortionRemap>(image_, distortion_);
    }
  } else {
    image_.k = info.RectifiedIntrinsics();
    // camera_display.cpp updateCamera: "the camera's translation relative to the left camera"
    if (!info.P.isZero()) offset_C_ = {-info.P(0, 3) / image_.k.fx, -info.P(1, 3) / image_.k.fy, 0};
  }
}

CameraModel::CameraModel(double fov_y, int width, int height, Clipping clipping)
    : image_{CentredIntrinsics(fov_y, width, height), width, height}, clipping_(clipping) {}

Eigen::Isometry3d CameraModel::Pose(const Eigen::Isometry3d& X_WF) const {
  return X_WF * Eigen::Translation3d(offset_C_);
}

std::optional<Eigen::Vector2d> CameraModel::Project(const Eigen::Vector3d& p_C) const {
  if (!(p_C.z() > 0)) return std::nullopt;
  const Eigen::Vector2d ideal = p_C.head<2>() / p_C.z();
  return ToPixel(image_.k, remap_ ? Distort(distortion_, ideal) : ideal);
}

const PinholeImage& CameraModel::drawn() const { return remap_ ? remap_->source() : image_; }

Eigen::Matrix4d CameraModel::GlProjection() const {
  const PinholeImage& d = drawn();
  return camera::GlProjection(d.k, d.width, d.height, clipping_.near, clipping_.far);
}

image::Frame CameraModel::Finish(image::Frame drawn) const {
  // returned by name, so moved: the conditional operator copied all three images of every frame
  if (!remap_) return drawn;
  return remap_->Apply(drawn);
}

Eigen::Matrix4d GlViewMatrix(const Eigen::Isometry3d& X_WC) {
  // the GL camera frame G is the optical frame C turned 180° about x: y up, looking down −z
  Eigen::Isometry3d X_CG = Eigen::Isometry3d::Identity();
  X_CG.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
  return (X_WC * X_CG).inverse().matrix();
}

}  // namespace urdfsnap::camera
