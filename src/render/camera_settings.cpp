// OrbitCamera: RViz's orbit view as a camera::CameraModel and an optical-frame pose.
#include "render/camera_settings.h"

namespace urdfsnap::render {

CameraSettings OrbitCamera(const scene::OrbitView& view, int width, int height) {
  CameraSettings camera;
  camera.model = std::make_shared<const camera::CameraModel>(view.fov_y, width, height,
                                                             camera::Clipping{view.near_clip, view.far_clip});
  // the GL eye frame G (looking down −z, y up) turned 180° about x is the optical frame
  Eigen::Isometry3d X_FG(scene::ViewMatrix(view).inverse());
  camera.pose = X_FG * Eigen::Isometry3d(Eigen::Matrix3d(Eigen::Vector3d(1, -1, -1).asDiagonal()));
  return camera;
}

}  // namespace urdfsnap::render
